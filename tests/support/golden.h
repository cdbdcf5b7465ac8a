// Golden-image checks for the chapter tests.
#pragma once

#include <string>
#include <vector>

#include "cgfs/canvas.h"
#include "cgfs/figure.h"

namespace cgfs::test {

// The size every golden image is rendered at.
inline constexpr int kGoldenWidth = 600;
inline constexpr int kGoldenHeight = 600;

// The figure of that name (a test failure if the chapter has none).
const Figure& FindFigure(const std::vector<Figure>& figures, const std::string& name);

// Draws the named figure at 600x600.
Canvas RenderFigureNamed(const std::vector<Figure>& figures, const std::string& name);

// tests/golden/<chapter>/<name>.png
std::string GoldenFile(const std::string& chapter, const std::string& name);

// Draws the named figure at 600x600 and compares it with
// tests/golden/<chapter>/<name>.png under the project's tolerance. On failure the
// actual and a difference image are written to <build>/test-output/<chapter>/
// and their paths are printed with the numbers.
void CheckAgainstGolden(const std::string& chapter, const std::vector<Figure>& figures,
                        const std::string& name);

}  // namespace cgfs::test
