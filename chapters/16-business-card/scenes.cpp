#include "scenes.h"

#include <string>

namespace {

// A figure of the card drawn with `settings`, whose eye --window and --view can move.
cgfs::Figure CardFigure(const std::string& name, const std::string& caption,
                        const RenderSettings& settings) {
  return {
      name, caption, [settings](cgfs::Canvas& canvas) { Render(canvas, settings); },
      [settings](cgfs::Canvas& canvas, const cgfs::View& view) { Render(canvas, settings, view); }};
}

}  // namespace

std::vector<cgfs::Figure> Figures(const ChapterSettings& settings) {
  const RenderSettings card = settings.card;
  RenderSettings one_sample = card;
  one_sample.samples = 1;
  RenderSettings stratified = card;
  stratified.samples = kStratifiedSamples;
  stratified.stratified = true;
  return {
      CardFigure("business-card",
                 "the card's image: \"aek\" in mirror spheres, " + std::to_string(card.samples) +
                     " samples per pixel",
                 card),
      CardFigure("business-card-1-sample", "one sample per pixel: why the card takes 64",
                 one_sample),
      CardFigure("business-card-stratified",
                 std::to_string(kStratifiedSamples) +
                     " low-discrepancy samples per pixel: less noise than the card's 64, in "
                     "under half the time",
                 stratified),
  };
}
