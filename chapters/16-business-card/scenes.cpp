#include "scenes.h"

#include <string>

std::vector<cgfs::Figure> Figures(const ChapterSettings& settings) {
  const RenderSettings card = settings.card;
  RenderSettings one_sample = card;
  one_sample.samples = 1;
  RenderSettings stratified = card;
  stratified.samples = kStratifiedSamples;
  stratified.stratified = true;
  return {
      {"business-card",
       "the card's image: \"aek\" in mirror spheres, " + std::to_string(card.samples) +
           " samples per pixel",
       [card](cgfs::Canvas& canvas) { Render(canvas, card); }},
      {"business-card-1-sample", "one sample per pixel: why the card takes 64",
       [one_sample](cgfs::Canvas& canvas) { Render(canvas, one_sample); }},
      {"business-card-stratified",
       std::to_string(kStratifiedSamples) +
           " low-discrepancy samples per pixel: less noise than the card's 64, in "
           "under half the time",
       [stratified](cgfs::Canvas& canvas) { Render(canvas, stratified); }},
  };
}
