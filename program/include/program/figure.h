// A figure a chapter draws: its file name, what it shows, and how to draw it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "cgfs/canvas.h"
#include "cgfs/view.h"

namespace cgfs {

struct Figure {
  std::string name;     // file name without extension, e.g. "fig-2-11"
  std::string caption;  // one line: what the figure shows
  // Draws onto a canvas of the requested size, cleared to white.
  std::function<void(Canvas&)> draw;
  // The same from a moved camera; empty for a figure without a camera to move.
  std::function<void(Canvas&, const View&)> draw_from = {};
  // The figure that shows where this one's work goes (program/cost_view.h), which the
  // C key switches to; empty if there is none.
  std::string cost_view = {};
  // What the figure's last draw measured, said after its caption (a cost view's totals,
  // for the size and view drawn: "13 414 717 in all, at most 292"); empty when it
  // measures nothing.
  std::function<std::string()> measured = {};
};

// The caption of a figure once drawn: with what its draw measured, if anything.
std::string CaptionOfDrawn(const Figure& figure);

// Gives the figure named `name` the cost view named `cost_view` (the C key's pair);
// std::logic_error if the list has no figure of either name.
void SetCostView(std::vector<Figure>& figures, const std::string& name,
                 const std::string& cost_view);

// The index in `figures` of the figure the C key switches to from figures[index]: its
// cost view, or the figure whose cost view it is; -1 when neither is in the list.
int CostPartner(const std::vector<const Figure*>& figures, std::size_t index);

// Draws one figure on a fresh white canvas of the given size, from `view` (which must
// be the chapter's own for a figure without a camera: cgfs::UsageError otherwise).
Canvas RenderFigure(const Figure& figure, int width, int height, const View& view = {});

// A view as --view takes it and --window prints it: "x,y,z,yaw,pitch".
std::string FormatView(const View& view);
// The view of such text; cgfs::UsageError with one line if it is not one.
View ParseView(const std::string& text);

}  // namespace cgfs
