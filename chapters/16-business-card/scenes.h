// The card's figures.
#pragma once

#include <cstdint>
#include <vector>

#include "cgfs/figure.h"
#include "render.h"

inline constexpr char kChapterDescription[] =
    "Bonus: Andrew Kensler's business-card ray tracer, readable: the letters \"aek\" in "
    "mirror spheres on a checkered floor, soft shadows, depth of field.";

inline constexpr std::uint32_t kDefaultSeed = 1;

// The samples per pixel and the seed of the card's figure: 64 and 1 unless the
// command line says otherwise (options.h).
int& ChosenSamples();
std::uint32_t& ChosenSeed();

// Every figure this chapter draws.
std::vector<cgfs::Figure> Figures();
