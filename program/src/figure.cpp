#include "program/figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "program/error.h"

namespace cgfs {

Canvas RenderFigure(const Figure& figure, int width, int height, const View& view) {
  Canvas canvas(width, height);
  if (view == View{}) {
    figure.draw(canvas);
  } else if (figure.draw_from) {
    figure.draw_from(canvas, view);
  } else {
    throw UsageError("figure '" + figure.name + "' has no camera to move (--view)");
  }
  return canvas;
}

void SetCostView(std::vector<Figure>& figures, const std::string& name,
                 const std::string& cost_view) {
  const auto named = [&](const std::string& wanted) {
    return std::find_if(figures.begin(), figures.end(),
                        [&](const Figure& figure) { return figure.name == wanted; });
  };
  const auto figure = named(name);
  if (figure == figures.end() || named(cost_view) == figures.end()) {
    throw std::logic_error("SetCostView: no figure " + name + " or " + cost_view);
  }
  figure->cost_view = cost_view;
}

std::string CaptionOfDrawn(const Figure& figure) {
  const std::string measured = figure.measured ? figure.measured() : "";
  return measured.empty() ? figure.caption : figure.caption + ": " + measured;
}

int CostPartner(const std::vector<const Figure*>& figures, std::size_t index) {
  const Figure& shown = *figures.at(index);
  for (std::size_t i = 0; i < figures.size(); ++i) {
    if ((!shown.cost_view.empty() && figures[i]->name == shown.cost_view) ||
        figures[i]->cost_view == shown.name) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

namespace {

// `value` in the fewest significant digits that read back as the same double, and at
// least as many as its whole part has, so that -10 is not written -1e+01.
// (std::to_chars does this, but emscripten's C++ library, for the web pages, lacks it.)
std::string Shortest(double value) {
  char digits[32];
  const double magnitude = std::abs(value);
  const int whole_digits = magnitude >= 1 ? static_cast<int>(std::log10(magnitude)) + 1 : 1;
  for (int precision = std::min(whole_digits, 17); precision <= 17; ++precision) {
    std::snprintf(digits, sizeof digits, "%.*g", precision, value);
    if (std::strtod(digits, nullptr) == value) {
      break;
    }
  }
  return digits;
}

}  // namespace

std::string FormatView(const View& view) {
  // Every number read back exactly, so that the same view draws the same image, in as
  // few digits as that takes: 2.2, not 2.2000000000000002.
  return Shortest(view.move.x) + "," + Shortest(view.move.y) + "," + Shortest(view.move.z) + "," +
         Shortest(view.yaw) + "," + Shortest(view.pitch);
}

View ParseView(const std::string& text) {
  std::istringstream in(text);
  double values[5];
  char comma = ',';
  constexpr double kLargest = 1e6;  // a camera a million units away sees nothing of a scene
  constexpr const char* kNames[] = {"x", "y", "z", "yaw", "pitch"};
  for (int i = 0; i < 5; ++i) {
    if ((i > 0 && (!(in >> comma) || comma != ',')) || !(in >> values[i])) {
      throw UsageError("'" + text + "' is not five numbers x,y,z,yaw,pitch");
    }
    if (!std::isfinite(values[i]) || std::abs(values[i]) > kLargest) {
      throw UsageError("'" + text + "': " + kNames[i] +
                       " is out of range (at most 1e6 either way)");
    }
  }
  if (in >> comma) {
    throw UsageError("'" + text + "' is not five numbers x,y,z,yaw,pitch");
  }
  return {{values[0], values[1], values[2]}, values[3], values[4]};
}

}  // namespace cgfs
