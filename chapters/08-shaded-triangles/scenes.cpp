#include "scenes.h"

namespace {

// The triangle of "Drawing Filled Triangles", now with an intensity h at each vertex.
constexpr Point kP0{-200, -250, 0.3}, kP1{200, 50, 0.1}, kP2{20, 250, 1.0};

}  // namespace

std::vector<cgfs::Figure> Figures() {
  return {
      {"fig-8-1", "a shaded triangle: h = 0.3, 0.1 and 1.0 at its vertices (Figure 8-1)",
       [](Canvas& canvas) { DrawShadedTriangle(kP0, kP1, kP2, cgfs::kGreen, canvas); }},
  };
}
