// Golden-image checks for the chapter tests.
#pragma once

#include <string>
#include <vector>

#include "cgfs/canvas.h"
#include "program/figure.h"

namespace cgfs::test {

// The size golden images are rendered at: the programs' default size, which every
// chapter keeps but the bonus business card (512x512, the card's own size).
inline constexpr int kGoldenWidth = 600;
inline constexpr int kGoldenHeight = 600;

// The figure of that name (a test failure if the chapter has none).
const Figure& FindFigure(const std::vector<Figure>& figures, const std::string& name);

// Draws the named figure at 600x600 (once per test program: see golden.cpp).
Canvas RenderFigureNamed(const std::vector<Figure>& figures, const std::string& name);
// What that drawing said it measured (Figure::measured), "" for nothing.
std::string MeasuredByFigureNamed(const std::vector<Figure>& figures, const std::string& name);

// tests/golden/<chapter>/<name>.png
std::string GoldenFile(const std::string& chapter, const std::string& name);

// Draws the named figure at the size of its golden image (600x600 but for the
// business card) and compares it with tests/golden/<chapter>/<name>.png under the
// project's tolerance. On failure the actual and a difference image are written to
// <build>/test-output/<chapter>/ and their paths are printed with the numbers.
void CheckAgainstGolden(const std::string& chapter, const std::vector<Figure>& figures,
                        const std::string& name);

// The same for an image the test has drawn already.
void CheckImageAgainstGolden(const std::string& chapter, const std::string& name,
                             const Image& actual);

}  // namespace cgfs::test
