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
    long long differing = 0;
    for (int row = 0; row < actual.Height(); ++row) {
      for (int column = 0; column < actual.Width(); ++column) {
        if (actual.At(column, row) != expected_.At(column, row) && differing++ == 0) {
          difference_ = FirstDifference(actual, column, row);
        }
      }
    }
    if (differing > 0) {
      difference_ = std::to_string(differing) + " of " +
                    std::to_string(static_cast<long long>(actual.Width()) * actual.Height()) +
                    " pixels differ; the first " + difference_;
    }
    return differing == 0;
  }

  std::string describe() const override {
    return "is the same image as " + Catch::StringMaker<Image>::convert(expected_) +
           (difference_.empty() ? "" : " (" + difference_ + ")");
  }

 private:
  std::string FirstDifference(const Image& actual, int column, int row) const {
    return "at canvas (" + std::to_string(column - actual.Width() / 2) + ", " +
           std::to_string(actual.Height() / 2 - row - 1) +
           "): " + Catch::StringMaker<Rgb8>::convert(actual.At(column, row)) + " instead of " +
           Catch::StringMaker<Rgb8>::convert(expected_.At(column, row));
  }

  Image expected_;
  mutable std::string difference_;  // what match() found, for describe()
};

}  // namespace cgfs::test
