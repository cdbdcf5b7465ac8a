// The figures of the chapter.
#pragma once

#include <vector>

#include "lines.h"
#include "program/figure.h"

inline constexpr char kChapterDescription[] =
    "Chapter 6, Lines: DrawLine for any slope, and Interpolate.";

// Every figure this chapter draws.
std::vector<cgfs::Figure> Figures();
