// The figures of the chapter.
#pragma once

#include <vector>

#include "program/figure.h"
#include "triangles.h"

inline constexpr char kChapterDescription[] =
    "Chapter 7, Filled Triangles: wireframe triangles, and filled ones as horizontal segments.";

// Every figure this chapter draws.
std::vector<cgfs::Figure> Figures();
