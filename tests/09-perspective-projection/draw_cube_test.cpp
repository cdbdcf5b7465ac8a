// Listing 9-1's cube, drawn when part of it cannot be projected.
#include <catch2/catch.hpp>

#include "rasterizer.h"

TEST_CASE("DrawCube skips the edges it cannot project, without crashing", "[projection]") {
  // A cube around the camera: its front face is behind it, its back face 2 units ahead.
  const Cube around{{-1, 1, -1}, {1, 1, -1}, {1, -1, -1}, {-1, -1, -1},
                    {-1, 1, 2},  {1, 1, 2},  {1, -1, 2},  {-1, -1, 2}};
  Canvas canvas(600, 600);
  DrawCube(around, canvas, Viewport{});
  Canvas back_face(600, 600);
  DrawLine({-300, 300}, {300, 300}, cgfs::kRed, back_face);
  DrawLine({300, 300}, {300, -300}, cgfs::kRed, back_face);
  DrawLine({300, -300}, {-300, -300}, cgfs::kRed, back_face);
  DrawLine({-300, -300}, {-300, 300}, cgfs::kRed, back_face);
  // Only the back face is drawn: the front face and the front-to-back edges are skipped.
  CHECK(canvas.GetImage() == back_face.GetImage());
}
