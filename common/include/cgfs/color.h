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
// nearest integer with std::lround (docs/conventions.md, "Colours").
std::uint8_t ToChannel(double value);

}  // namespace cgfs
