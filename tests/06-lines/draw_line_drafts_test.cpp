// What the chapter's earlier versions of DrawLine get wrong.
#include <catch2/catch.hpp>

#include <set>
#include <utility>

#include "draw_line_drafts.h"
#include "pixels.h"

using cgfs::test::DrawnPixels;
using Pixels = std::set<std::pair<int, int>>;

namespace {

using DrawLineFunction = void (*)(Point, Point, const Color&, Canvas&);

Pixels DraftPixels(DrawLineFunction draw_line, Point P0, Point P1) {
  Canvas canvas(600, 600);
  draw_line(P0, P1, cgfs::kBlack, canvas);
  return DrawnPixels(canvas);
}

}  // namespace

TEST_CASE("the left-to-right draft leaves gaps in a steep line", "[drafts]") {
  // One pixel per column: 111 columns for a segment 440 pixels tall.
  CHECK(DraftPixels(DrawLineLeftToRight, {-50, -200}, {60, 240}).size() == 111);
  CHECK(DraftPixels(DrawLineLeftToRight, {-200, -100}, {240, 120}).size() == 441);
}

TEST_CASE("the first two drafts draw nothing from right to left", "[drafts]") {
  CHECK(DraftPixels(DrawLineSlopeIntercept, {240, 120}, {-200, -100}).empty());
  CHECK(DraftPixels(DrawLineIncremental, {240, 120}, {-200, -100}).empty());
  CHECK(DraftPixels(DrawLineSlopeIntercept, {-200, -100}, {240, 120}).size() == 441);
}

TEST_CASE("the drafts divide by zero on a vertical line without crashing", "[drafts]") {
  // a = dy / 0 is infinite: the book's versions cannot draw this line.
  for (const DrawLineFunction draft :
       {DrawLineSlopeIntercept, DrawLineIncremental, DrawLineLeftToRight}) {
    CHECK(DraftPixels(draft, {3, -7}, {3, 7}).size() <= 1);
  }
  CHECK(DraftPixels(DrawLineXOfY, {3, -7}, {3, 7}).size() == 15);
}

TEST_CASE("x = f(y) draws (0,0)-(50,100) but breaks (0,0)-(100,50)", "[drafts]") {
  CHECK(DraftPixels(DrawLineXOfY, {0, 0}, {50, 100}).size() == 101);
  CHECK(DraftPixels(DrawLineXOfY, {0, 0}, {100, 50}).size() == 51);
}

TEST_CASE("Listing 6-1 already handles every case", "[drafts]") {
  CHECK(DraftPixels(DrawLineBothCases, {-50, -200}, {60, 240}).size() == 441);
  CHECK(DraftPixels(DrawLineBothCases, {240, 120}, {-200, -100}).size() == 441);
  CHECK(DraftPixels(DrawLineBothCases, {3, -7}, {3, 7}).size() == 15);
}
