#include "rasterizer.h"

namespace {

// The two segments of "Drawing Lines": a shallow one and a steep one.
constexpr Point kShallowFrom{-200, -100}, kShallowTo{240, 120};
constexpr Point kSteepFrom{-50, -200}, kSteepTo{60, 240};

// Sixteen segments from the centre, 22.5 degrees apart (radius 250, rounded).
// Every other one is given outside-in, so both end-point orders are drawn.
constexpr Point kStarTips[] = {{250, 0},  {231, 96},   {177, 177},   {96, 231},
                               {0, 250},  {-96, 231},  {-177, 177},  {-231, 96},
                               {-250, 0}, {-231, -96}, {-177, -177}, {-96, -231},
                               {0, -250}, {96, -231},  {177, -177},  {231, -96}};

template <typename DrawFunction>
void DrawStar(DrawFunction draw) {
  bool outwards = true;
  for (const Point& tip : kStarTips) {
    if (outwards) {
      draw(Point{0, 0}, tip);
    } else {
      draw(tip, Point{0, 0});
    }
    outwards = !outwards;
  }
}

}  // namespace

std::vector<cgfs::Figure> Figures(const std::vector<DrawLineDraft>& drafts) {
  std::vector<cgfs::Figure> figures = {
      {"fig-6-1", "the shallow segment, drawn left to right with y = f(x) (Figure 6-1)",
       [](Canvas& canvas) {
         DrawLineDraftVersion(DrawLineDraft::kLeftToRight, kShallowFrom, kShallowTo, cgfs::kBlack,
                              canvas);
       }},
      {"fig-6-3", "both segments with y = f(x): the steep one falls apart (Figure 6-3)",
       [](Canvas& canvas) {
         DrawLineDraftVersion(DrawLineDraft::kLeftToRight, kShallowFrom, kShallowTo, cgfs::kBlack,
                              canvas);
         DrawLineDraftVersion(DrawLineDraft::kLeftToRight, kSteepFrom, kSteepTo, cgfs::kBlack,
                              canvas);
       }},
      {"fig-6-5", "both segments with the final DrawLine (Figure 6-5)",
       [](Canvas& canvas) {
         DrawLine(kShallowFrom, kShallowTo, cgfs::kBlack, canvas);
         DrawLine(kSteepFrom, kSteepTo, cgfs::kBlack, canvas);
       }},
      {"all-directions", "sixteen directions, both end-point orders, with the final DrawLine",
       [](Canvas& canvas) {
         DrawStar([&](Point P0, Point P1) { DrawLine(P0, P1, cgfs::kBlack, canvas); });
       }},
  };
  for (const DrawLineDraft draft : drafts) {
    figures.push_back(
        {"all-directions-" + DraftName(draft),
         "sixteen directions drawn with the draft DrawLine '" + DraftName(draft) + "'",
         [draft](Canvas& canvas) {
           DrawStar([&](Point P0, Point P1) {
             DrawLineDraftVersion(draft, P0, P1, cgfs::kBlack, canvas);
           });
         }});
  }
  return figures;
}
