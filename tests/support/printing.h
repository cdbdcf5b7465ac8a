// Lets Catch2 print GLM vectors, colours and images in failed checks, instead of {?}.
#pragma once

#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <utility>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "cgfs/image.h"
#include "comparison/compare.h"

namespace Catch {

template <glm::length_t L>
struct StringMaker<glm::vec<L, double, glm::defaultp>> {
  static std::string convert(const glm::vec<L, double, glm::defaultp>& v) {
    std::ostringstream out;
    out.precision(10);
    out << "(";
    for (glm::length_t i = 0; i < L; ++i) {
      out << (i ? ", " : "") << v[i];
    }
    out << ")";
    return out.str();
  }
};

template <>
struct StringMaker<cgfs::Rgb8> {
  static std::string convert(const cgfs::Rgb8& c) {
    return "rgb(" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) +
           ")";
  }
};

template <>
struct StringMaker<cgfs::Image> {
  static std::string convert(const cgfs::Image& image) {
    return "a " + std::to_string(image.Width()) + "x" + std::to_string(image.Height()) + " image";
  }
};

}  // namespace Catch

namespace cgfs::test {

// CHECK_THAT(actual, IsSameImageAs(expected)): the two images are equal pixel for pixel.
// When they are not, the failed check says how: their sizes, or how many pixels differ
// and the first of them (reading from the top left) in canvas coordinates, with both
// colours, where `CHECK(actual == expected)` could only print {?} == {?}.
class IsSameImageAs : public Catch::MatcherBase<Image> {
 public:
  explicit IsSameImageAs(Image expected) : expected_(std::move(expected)) {}

  bool match(const Image& actual) const override {
    if (actual.Width() != expected_.Width() || actual.Height() != expected_.Height()) {
      difference_ = "sizes differ";
      return false;
    }
    // cgfs-compare's comparison with no tolerance at all: any changed pixel counts.
    const Comparison exact = CompareImages(expected_, actual, {0, 0.0});
    if (exact.differing_pixels > 0) {
      const Comparison::Pixel& first = exact.first_differing;
      difference_ = std::to_string(exact.differing_pixels) + " of " + std::to_string(exact.pixels) +
                    " pixels differ; the first at canvas (" +
                    std::to_string(first.column - actual.Width() / 2) + ", " +
                    std::to_string(actual.Height() / 2 - first.row - 1) +
                    "): " + Catch::StringMaker<Rgb8>::convert(first.yours) + " instead of " +
                    Catch::StringMaker<Rgb8>::convert(first.ours);
    }
    return exact.differing_pixels == 0;
  }

  std::string describe() const override {
    return "is the same image as " + Catch::StringMaker<Image>::convert(expected_) +
           (difference_.empty() ? "" : " (" + difference_ + ")");
  }

 private:
  Image expected_;
  mutable std::string difference_;  // what match() found, for describe()
};

}  // namespace cgfs::test
