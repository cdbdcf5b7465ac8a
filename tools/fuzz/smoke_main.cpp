// fuzz-smoke [MUTATIONS]: the fuzz target run over its seeds and over deterministic
// mutations of them (flipped bits, bytes set to 0 or 255, cut short, a run repeated),
// in one process, with any compiler: a short fuzz run for the ordinary tests. A crash,
// a hang or a sanitizer report fails it; scripts/fuzz runs the real fuzzer.
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>

#include "seeds.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

void Run(const std::string& bytes) {
  LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

std::string Mutate(std::string bytes, std::mt19937& random) {
  if (bytes.empty()) {
    return bytes;
  }
  const auto at = [&] {
    return std::uniform_int_distribution<std::size_t>(0, bytes.size() - 1)(random);
  };
  switch (random() % 5) {
    case 0:
      bytes[at()] ^= static_cast<char>(1 << (random() % 8));
      break;
    case 1:
      bytes[at()] = static_cast<char>(random() % 2 ? 0 : 255);
      break;
    case 2:
      bytes.resize(at());
      break;
    case 3: {
      const std::size_t from = at();
      bytes.insert(from, bytes.substr(from, 1 + random() % 64));
      break;
    }
    default:
      for (int k = 0; k < 4; ++k) {
        bytes[at()] = static_cast<char>(random());
      }
  }
  return bytes;
}

}  // namespace

int main(int argc, char** argv) {
  const long mutations = argc > 1 ? std::atol(argv[1]) : 20000;
  std::mt19937 random(20261123);
  const auto seeds = cgfs::fuzz::MakeSeeds();
  for (const auto& [name, bytes] : seeds) {
    Run(bytes);
  }
  for (long k = 0; k < mutations; ++k) {
    const std::string& seed = seeds[static_cast<std::size_t>(k) % seeds.size()].second;
    std::string bytes = Mutate(seed, random);
    for (int more = static_cast<int>(random() % 4); more > 0; --more) {
      bytes = Mutate(bytes, random);
    }
    Run(bytes);
  }
  std::cout << "fuzz-smoke: " << seeds.size() << " seeds and " << mutations
            << " mutations decoded or refused\n";
  return 0;
}
