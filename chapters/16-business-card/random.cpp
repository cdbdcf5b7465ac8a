#include "random.h"

namespace {

std::ranlux24_base SeededEngine(std::uint32_t image_seed, int x, int y) {
  // std::seed_seq mixes the three numbers into the engine's whole state, so that
  // neighbouring pixels, whose x differ by one, get unrelated numbers.
  std::seed_seq numbers{image_seed, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y)};
  return std::ranlux24_base(numbers);
}

}  // namespace

Random::Random(std::uint32_t seed, int x, int y) : engine_(SeededEngine(seed, x, y)) {}
