// A figure a chapter draws: its file name, what it shows, and how to draw it.
#pragma once

#include <functional>
#include <string>

#include "cgfs/canvas.h"

namespace cgfs {

struct Figure {
  std::string name;     // file name without extension, e.g. "fig-2-11"
  std::string caption;  // one line: what the figure shows
  // Draws onto a canvas of the requested size, cleared to white.
  std::function<void(Canvas&)> draw;
};

// Draws one figure on a fresh white canvas of the given size.
Canvas RenderFigure(const Figure& figure, int width, int height);

}  // namespace cgfs
