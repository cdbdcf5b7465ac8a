#include "cgfs/color.h"

#include <algorithm>
#include <cmath>

namespace cgfs {

std::uint8_t ToChannel(double value) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0, 255.0)));
}

}  // namespace cgfs
