// ViewportToCanvas and ProjectVertex. Chapters 10 and 11 keep them and
// run these tests too.
#include <catch2/catch.hpp>

#include "projection.h"

TEST_CASE("ViewportToCanvas scales viewport units to pixels, truncating", "[projection]") {
  const Canvas canvas(600, 600);
  CHECK(ViewportToCanvas(0.5, -0.25, canvas, Viewport{}) == Point{300, -150});
  // -0.5 and 0.5 pixels both truncate toward zero.
  CHECK(ViewportToCanvas(-1.0 / 1200, 1.0 / 1200, canvas, Viewport{}) == Point{0, 0});
  // A wider viewport shows more of the plane, so the same point lands nearer the centre.
  CHECK(ViewportToCanvas(0.5, 0.5, canvas, Viewport{2, 2, 1}) == Point{150, 150});
}

TEST_CASE("ProjectVertex: the corners of the demo cube", "[projection]") {
  const Canvas canvas(600, 600);
  CHECK(ProjectVertex({-2, -0.5, 5}, canvas, Viewport{}) == Point{-240, -60});
  CHECK(ProjectVertex({-1, 0.5, 6}, canvas, Viewport{}) == Point{-100, 50});
  CHECK(ProjectVertex({-2, 0.5, 6}, canvas, Viewport{}) == Point{-200, 50});
  CHECK(ProjectVertex({-1, -0.5, 5}, canvas, Viewport{}) == Point{-120, -60});
}

TEST_CASE("ProjectVertex: the book's cube lands off the canvas", "[projection]") {
  const Canvas canvas(600, 600);
  CHECK(ProjectVertex({-1, 1, 1}, canvas, Viewport{}) == Point{-600, 600});
  CHECK(ProjectVertex({1, -1, 2}, canvas, Viewport{}) == Point{300, -300});
}

TEST_CASE("ProjectVertex: farther is smaller; the distance d scales the picture", "[projection]") {
  const Canvas canvas(600, 600);
  CHECK(ProjectVertex({1, 1, 5}, canvas, Viewport{}) == Point{120, 120});
  CHECK(ProjectVertex({1, 1, 10}, canvas, Viewport{}) == Point{60, 60});
  CHECK(ProjectVertex({1, 1, 10}, canvas, Viewport{1, 1, 2}) == Point{120, 120});
  // On the projection plane itself a point stays where it is: (0.5, 0.5) is the corner.
  CHECK(ProjectVertex({0.5, 0.5, 1}, canvas, Viewport{}) == Point{300, 300});
}
