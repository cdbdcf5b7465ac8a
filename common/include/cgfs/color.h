// Colours (book chapter 1, "Color models" and "Color manipulation").
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

namespace cgfs {

// A colour is three doubles (r, g, b) on the 0..255 scale. Intermediate results
// may leave that range (a bright light can push a channel above 255); they are
// clamped only when a pixel is written. GLM gives us k*color and color+color.
using Color = glm::dvec3;

inline constexpr Color kRed{255, 0, 0};
inline constexpr Color kGreen{0, 255, 0};
inline constexpr Color kBlue{0, 0, 255};
inline constexpr Color kYellow{255, 255, 0};
inline constexpr Color kPurple{255, 0, 255};
inline constexpr Color kCyan{0, 255, 255};
inline constexpr Color kBlack{0, 0, 0};
inline constexpr Color kWhite{255, 255, 255};

// One 8-bit channel as stored in an image: clamp to [0, 255], then round to the
// nearest integer, halves up, as std::lround rounds (docs/conventions.md,
// "Colours"); NaN gives 0. Written out rather than calling std::lround because every
// pixel of every figure goes through it: value - whole is exact for 0 < value < 255.
inline std::uint8_t ToChannel(double value) {
  if (!(value > 0)) {
    return 0;
  }
  if (value >= 255) {
    return 255;
  }
  const int whole = static_cast<int>(value);
  return static_cast<std::uint8_t>(value - whole >= 0.5 ? whole + 1 : whole);
}

}  // namespace cgfs
