// Spec §7.2-7.4: what the chapter's earlier versions of DrawLine get wrong.
#include <catch2/catch.hpp>

#include <set>
#include <utility>

#include "pixels.h"
#include "rasterizer.h"

using cgfs::test::DrawnPixels;
using Pixels = std::set<std::pair<int, int>>;

namespace {

Pixels DraftPixels(DrawLineDraft version, Point P0, Point P1) {
  Canvas canvas(600, 600);
  DrawLineDraftVersion(version, P0, P1, cgfs::kBlack, canvas);
  return DrawnPixels(canvas);
}

}  // namespace

TEST_CASE("the left-to-right draft leaves gaps in a steep line", "[drafts]") {
  // One pixel per column: 111 columns for a segment 440 pixels tall.
  CHECK(DraftPixels(DrawLineDraft::kLeftToRight, {-50, -200}, {60, 240}).size() == 111);
  CHECK(DraftPixels(DrawLineDraft::kLeftToRight, {-200, -100}, {240, 120}).size() == 441);
}

TEST_CASE("the first two drafts draw nothing from right to left", "[drafts]") {
  CHECK(DraftPixels(DrawLineDraft::kSlopeIntercept, {240, 120}, {-200, -100}).empty());
  CHECK(DraftPixels(DrawLineDraft::kIncremental, {240, 120}, {-200, -100}).empty());
  CHECK(DraftPixels(DrawLineDraft::kSlopeIntercept, {-200, -100}, {240, 120}).size() == 441);
}

TEST_CASE("the drafts divide by zero on a vertical line without crashing", "[drafts]") {
  // a = dy / 0 is infinite: the book's versions cannot draw this line.
  for (const DrawLineDraft draft :
       {DrawLineDraft::kSlopeIntercept, DrawLineDraft::kIncremental, DrawLineDraft::kLeftToRight}) {
    CHECK(DraftPixels(draft, {3, -7}, {3, 7}).size() <= 1);
  }
  CHECK(DraftPixels(DrawLineDraft::kXOfY, {3, -7}, {3, 7}).size() == 15);
}

TEST_CASE("x = f(y) draws (0,0)-(50,100) but breaks (0,0)-(100,50)", "[drafts]") {
  CHECK(DraftPixels(DrawLineDraft::kXOfY, {0, 0}, {50, 100}).size() == 101);
  CHECK(DraftPixels(DrawLineDraft::kXOfY, {0, 0}, {100, 50}).size() == 51);
}

TEST_CASE("Listing 6-1 already handles every case", "[drafts]") {
  CHECK(DraftPixels(DrawLineDraft::kBothCases, {-50, -200}, {60, 240}).size() == 441);
  CHECK(DraftPixels(DrawLineDraft::kBothCases, {240, 120}, {-200, -100}).size() == 441);
  CHECK(DraftPixels(DrawLineDraft::kBothCases, {3, -7}, {3, 7}).size() == 15);
}

TEST_CASE("every draft has a name the command line accepts", "[drafts]") {
  for (const DrawLineDraft draft : AllDrafts()) {
    DrawLineDraft parsed = DrawLineDraft::kSlopeIntercept;
    REQUIRE(DraftFromName(DraftName(draft), &parsed));
    CHECK(parsed == draft);
  }
  DrawLineDraft ignored;
  CHECK_FALSE(DraftFromName("bresenham", &ignored));
}
