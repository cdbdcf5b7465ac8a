#include "scenes.h"

namespace {

// The triangle of "Drawing Filled Triangles".
constexpr Point kP0{-200, -250}, kP1{200, 50}, kP2{20, 250};

}  // namespace

std::vector<cgfs::Figure> Figures() {
  return {
      {"fig-7-1", "a wireframe triangle (Figure 7-1)",
       [](Canvas& canvas) { DrawWireframeTriangle(kP0, kP1, kP2, cgfs::kBlack, canvas); }},
      {"fig-7-3",
       "the filled triangle in green, its wireframe drawn on top to check it (Figure 7-3)",
       [](Canvas& canvas) {
         DrawFilledTriangle(kP0, kP1, kP2, cgfs::kGreen, canvas);
         DrawWireframeTriangle(kP0, kP1, kP2, cgfs::kBlack, canvas);
       }},
  };
}
