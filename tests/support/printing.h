// Lets Catch2 print GLM vectors (and so colours) in failed checks, instead of {?}.
#pragma once

#include <catch2/catch.hpp>

#include <sstream>
#include <string>

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

}  // namespace Catch
