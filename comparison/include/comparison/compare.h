// Comparing two images under the project's one tolerance (docs/testing.md, "The tolerance").
// Used by the golden-image tests and by tools/cgfs-compare for students.
#pragma once

#include <string>

#include "cgfs/image.h"

namespace cgfs {

struct Tolerance {
  // A pixel "differs" when any of its channels is off by more than this many levels.
  int channel_levels = 2;
  // The images match when at most this share of the pixels differ
  // (36 pixels of a 600x600 image: room for a few edge pixels, not for a 10x10 block).
  double differing_fraction = 0.0001;

  long long AllowedDifferingPixels(long long pixels) const;
};

struct Comparison {
  long long pixels = 0;
  long long changed_pixels = 0;    // any channel differs at all
  long long differing_pixels = 0;  // beyond Tolerance::channel_levels
  long long allowed_differing_pixels = 0;
  int max_channel_difference = 0;
  double mean_channel_difference = 0;  // over every channel of every pixel
  // Bounding box (memory order, inclusive) of the differing pixels; valid when differing_pixels >
  // 0.
  int first_column = 0, first_row = 0, last_column = 0, last_row = 0;
  // The first differing pixel, reading from the top left, and its two colours.
  struct Pixel {
    int column = 0, row = 0;
    Rgb8 ours, yours;
  };
  Pixel first_differing;
  // The differing pixels by kind, against each image's background (its most common
  // colour): drawn in ours only, drawn in yours only, drawn or background in both
  // in another colour.
  long long missing_pixels = 0, extra_pixels = 0, recoloured_pixels = 0;
  bool passed = false;
  // When the images do not match but would if the actual one were moved by a
  // pixel, flipped, had its red and blue put back or its background repainted:
  // what happened, in words, and where to look.
  std::string diagnosis;
  // The expected image faded to pale grey, with the changed pixels in the colours
  // of kDifferenceColours.
  Image difference;
};

// The colours of Comparison::difference: each with its name and what it means. The
// first three are the differing pixels by kind, the last the changed pixels within the
// tolerance.
struct DifferenceColour {
  Rgb8 colour;
  const char* name;
  const char* meaning;
};
inline constexpr DifferenceColour kDifferenceColours[] = {
    {{230, 0, 0}, "red", "in ours only (missing)"},
    {{0, 80, 255}, "blue", "in yours only (extra)"},
    {{170, 0, 200}, "purple", "in both, other colour"},
    {{255, 170, 0}, "orange", "within the tolerance"},
};

// The colours in words: "red: in ours only (missing), blue: ..., purple: ...; orange:
// within the tolerance".
std::string DifferenceLegend();

// Throws std::invalid_argument when the sizes differ.
Comparison CompareImages(const Image& expected, const Image& actual,
                         const Tolerance& tolerance = {});

// A few lines with the numbers, for people. Positions are given in memory order
// (column, row from the top-left) and, for even sizes, in the book's canvas coordinates.
std::string Describe(const Comparison& comparison, int width, int height);

}  // namespace cgfs
