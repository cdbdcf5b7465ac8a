#include "scenes.h"

#include "draw_line_drafts.h"

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

using DrawLineFunction = void (*)(Point, Point, const Color&, Canvas&);

void DrawStar(DrawLineFunction draw_line, Canvas& canvas) {
  bool outwards = true;
  for (const Point& tip : kStarTips) {
    if (outwards) {
      draw_line(Point{0, 0}, tip, cgfs::kBlack, canvas);
    } else {
      draw_line(tip, Point{0, 0}, cgfs::kBlack, canvas);
    }
    outwards = !outwards;
  }
}

}  // namespace

std::vector<cgfs::Figure> Figures() {
  return {
      {"fig-6-1", "the shallow segment, drawn left to right with y = f(x) (Figure 6-1)",
       [](Canvas& canvas) { DrawLineLeftToRight(kShallowFrom, kShallowTo, cgfs::kBlack, canvas); }},
      {"fig-6-3", "both segments with y = f(x): the steep one falls apart (Figure 6-3)",
       [](Canvas& canvas) {
         DrawLineLeftToRight(kShallowFrom, kShallowTo, cgfs::kBlack, canvas);
         DrawLineLeftToRight(kSteepFrom, kSteepTo, cgfs::kBlack, canvas);
       }},
      {"fig-6-5", "both segments with the final DrawLine (Figure 6-5)",
       [](Canvas& canvas) {
         DrawLine(kShallowFrom, kShallowTo, cgfs::kBlack, canvas);
         DrawLine(kSteepFrom, kSteepTo, cgfs::kBlack, canvas);
       }},
      {"all-directions", "sixteen directions, both end-point orders, with the final DrawLine",
       [](Canvas& canvas) { DrawStar(DrawLine, canvas); }},
      {"all-directions-slope-intercept",
       "the same with DrawLineSlopeIntercept: nothing from right to left, nothing vertical",
       [](Canvas& canvas) { DrawStar(DrawLineSlopeIntercept, canvas); }},
      {"all-directions-incremental",
       "the same with DrawLineIncremental: y += a per pixel, the same gaps",
       [](Canvas& canvas) { DrawStar(DrawLineIncremental, canvas); }},
      {"all-directions-left-to-right",
       "the same with DrawLineLeftToRight: both orders, but steep lines break up and vertical ones "
       "vanish",
       [](Canvas& canvas) { DrawStar(DrawLineLeftToRight, canvas); }},
      {"all-directions-x-of-y",
       "the same with DrawLineXOfY: steep lines whole, shallow ones broken, horizontal ones gone",
       [](Canvas& canvas) { DrawStar(DrawLineXOfY, canvas); }},
      {"all-directions-both-cases",
       "the same with DrawLineBothCases (Listing 6-1): every line whole",
       [](Canvas& canvas) { DrawStar(DrawLineBothCases, canvas); }},
  };
}
