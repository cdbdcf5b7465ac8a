// Approximate comparisons of GLM vectors, component by component.
#pragma once

#include <catch2/catch.hpp>

#include <glm/vec3.hpp>

#include "printing.h"

namespace cgfs::test {

inline void CheckNear(const glm::dvec3& actual, const glm::dvec3& expected, double margin = 1e-6) {
  INFO("actual " << Catch::StringMaker<glm::dvec3>::convert(actual) << ", expected "
                 << Catch::StringMaker<glm::dvec3>::convert(expected));
  CHECK(actual.x == Approx(expected.x).margin(margin));
  CHECK(actual.y == Approx(expected.y).margin(margin));
  CHECK(actual.z == Approx(expected.z).margin(margin));
}

}  // namespace cgfs::test
