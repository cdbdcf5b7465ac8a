// The card's R(): a random number in [0, 1), here from a generator of our own per
// pixel instead of the C library's one rand() for everything.
//
// Each pixel's numbers come from a generator seeded with the image's seed and the
// pixel's position only, so the image is the same whatever order the pixels are
// drawn in, on one thread or many, and any pixel can be drawn again on its own.
#pragma once

#include <cstdint>
#include <random>

class Random {
 public:
  // The generator of pixel (x, y) of an image drawn with `seed`.
  Random(std::uint32_t seed, int x, int y);

  // The card's R(). A float, as on the card: 24 random bits are plenty for where a
  // ray starts and aims, and this engine makes 24 at a time (a double would take 3).
  // Numbers given to Preset come first.
  double Rand() {
    if (presets_ > 0) {
      return preset_[2 - presets_--];
    }
    return uniform_(engine_);
  }

  // The next two Rand() give u and v: the stratified card's point of the light for a
  // sample's first hit (render.h). ClearPreset forgets them if no hit used them.
  void Preset(double u, double v) {
    preset_[0] = u;
    preset_[1] = v;
    presets_ = 2;
  }
  void ClearPreset() { presets_ = 0; }

 private:
  double preset_[2] = {0, 0};
  int presets_ = 0;
  // A generator is made for every pixel, so it must be quick to make: this one of
  // the standard library has 24 numbers of state (std::mt19937 has 624, and makes a
  // card of a few samples a pixel several times as slow: README.md).
  std::ranlux24_base engine_;
  std::uniform_real_distribution<float> uniform_{0.0F, 1.0F};
};
