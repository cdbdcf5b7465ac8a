// The card's figures.
#pragma once

#include <vector>

#include "options.h"
#include "program/figure.h"
#include "render.h"

inline constexpr char kChapterDescription[] =
    "Bonus: Andrew Kensler's business-card ray tracer, readable: the letters \"aek\" in "
    "mirror spheres on a checkered floor, soft shadows, depth of field.";

// Every figure this chapter draws, made with `settings`.
std::vector<cgfs::Figure> Figures(const ChapterSettings& settings);
