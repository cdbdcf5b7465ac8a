// ViewportToCanvas and ProjectVertex, on their cases in
// tests/cases/09-perspective-projection.json (shared with the runners for other
// languages) and more. Chapters 10 to 15 keep them and run these tests too.
#include <catch2/catch.hpp>

#include <vector>

#include "cases.h"
#include "projection.h"

namespace {

Canvas CanvasOfProjectionCase(const nlohmann::json& given) {
  const nlohmann::json& size = given.at("canvas");
  return Canvas(size.at("width").get<int>(), size.at("height").get<int>());
}

Viewport ViewportOfProjectionCase(const nlohmann::json& given) {
  const nlohmann::json& viewport = given.at("viewport");
  return {viewport.at("width").get<double>(), viewport.at("height").get<double>(),
          viewport.at("d").get<double>()};
}

std::vector<double> PointAsNumbers(const Point& P) {
  return {static_cast<double>(P.x), static_cast<double>(P.y)};
}

}  // namespace

TEST_CASE("ViewportToCanvas: the cases of 09-perspective-projection.json", "[projection]") {
  using cgfs::test::ToNumber;
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("09-perspective-projection.json", "ViewportToCanvas")) {
    INFO(c.Describe());
    const Point P =
        ViewportToCanvas(ToNumber(c.args.at("x")), ToNumber(c.args.at("y")),
                         CanvasOfProjectionCase(c.given), ViewportOfProjectionCase(c.given));
    CHECK_THAT(PointAsNumbers(P), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("ProjectVertex: the cases of 09-perspective-projection.json", "[projection]") {
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("09-perspective-projection.json", "ProjectVertex")) {
    INFO(c.Describe());
    const Point P =
        ProjectVertex(cgfs::test::ToVector(c.args.at("v")), CanvasOfProjectionCase(c.given),
                      ViewportOfProjectionCase(c.given));
    CHECK_THAT(PointAsNumbers(P), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("ProjectVertex: the corners of the demo cube", "[projection]") {
  const Canvas canvas(600, 600);
  CHECK(ProjectVertex({-1, 0.5, 6}, canvas, Viewport{}) == Point{-100, 50});
  CHECK(ProjectVertex({-2, 0.5, 6}, canvas, Viewport{}) == Point{-200, 50});
  CHECK(ProjectVertex({-1, -0.5, 5}, canvas, Viewport{}) == Point{-120, -60});
}

TEST_CASE("ProjectVertex: the book's cube lands off the canvas", "[projection]") {
  const Canvas canvas(600, 600);
  CHECK(ProjectVertex({-1, 1, 1}, canvas, Viewport{}) == Point{-600, 600});
  CHECK(ProjectVertex({1, -1, 2}, canvas, Viewport{}) == Point{300, -300});
}

TEST_CASE("ProjectVertex: farther is smaller, and the distance d scales the picture",
          "[projection]") {
  const Canvas canvas(600, 600);
  CHECK(ProjectVertex({1, 1, 5}, canvas, Viewport{}) == Point{120, 120});
  CHECK(ProjectVertex({1, 1, 10}, canvas, Viewport{}) == Point{60, 60});
  CHECK(ProjectVertex({1, 1, 10}, canvas, Viewport{1, 1, 2}) == Point{120, 120});
  // On the projection plane itself a point stays where it is: (0.5, 0.5) is the corner.
  CHECK(ProjectVertex({0.5, 0.5, 1}, canvas, Viewport{}) == Point{300, 300});
}
