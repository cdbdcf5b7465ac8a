// The card's tracer T, with and without the bound.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "checks.h"
#include "letters.h"
#include "trace.h"

using cgfs::test::CheckNear;

TEST_CASE("Trace: straight down onto the floor", "[trace]") {
  double t = 0;
  glm::dvec3 n(9);
  CHECK(Trace({0, 0, 1}, {0, 0, -1}, t, n) == HitType::Floor);
  CHECK(t == Approx(1));
  CheckNear(n, {0, 0, 1});
}

TEST_CASE("Trace: along +y into the sphere (14, 0, 8)", "[trace]") {
  for (bool bounded : {false, true}) {
    double t = 0;
    glm::dvec3 n(9);
    CHECK(Trace({14, -5, 8}, {0, 1, 0}, t, n, bounded) == HitType::Sphere);
    CHECK(t == Approx(4));
    CheckNear(n, {0, -1, 0});
  }
}

TEST_CASE("Trace: the sky, and the floor seen past a sphere", "[trace]") {
  double t = 0;
  glm::dvec3 n(9);
  CHECK(Trace({0, 50, 8}, {0, 0, 1}, t, n) == HitType::Sky);
  CHECK(t == 1e9);
  // Straight down onto column 16 of "a": its top sphere is (16, 0, 10), met at z = 11.
  CHECK(Trace({16, 0, 20}, {0, 0, -1}, t, n) == HitType::Sphere);
  CHECK(t == Approx(9));
  CheckNear(n, {0, 0, 1});
  // Column 13, between "a" and "e", is empty: straight down onto the floor.
  CHECK(Trace({13, 0, 20}, {0, 0, -1}, t, n) == HitType::Floor);
  CHECK(t == Approx(20));
}

TEST_CASE("Trace: a ray parallel to the floor (d.z == 0) never meets it", "[trace]") {
  // The card computes -o.z / d.z = ±inf (or NaN from 0/0) there; here it is guarded.
  double t = 0;
  glm::dvec3 n(9);
  CHECK(Trace({0, 50, 8}, {1, 0, 0}, t, n) == HitType::Sky);
  CHECK(Trace({0, 50, 8}, {1, 0, -0.0}, t, n) == HitType::Sky);
  CHECK(Trace({0, 50, 0}, {1, 0, 0}, t, n) == HitType::Sky);
  CHECK(t == 1e9);
}

TEST_CASE("Trace finds the same hit with the bound as without, for rays of every kind",
          "[trace][bound]") {
  // Rays from the eye's neighbourhood and from points on and around the letters, in
  // every direction: the first kind are camera rays, the second shadow and mirror rays.
  std::mt19937 engine(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  int hits[3] = {0, 0, 0};
  for (int i = 0; i < 20000; ++i) {
    const glm::dvec3 origin =
        i % 2 == 0 ? glm::dvec3(17 + unit(engine), 16 + unit(engine), 8 + unit(engine))
                   : glm::dvec3(9 + 11 * unit(engine), 1.5 * unit(engine), 8 + 6 * unit(engine));
    glm::dvec3 direction(unit(engine), unit(engine), unit(engine));
    if (glm::length(direction) < 0.1) {
      continue;
    }
    direction = glm::normalize(direction);
    double t_plain = 0, t_bounded = 0;
    glm::dvec3 n_plain(9), n_bounded(9);
    const HitType plain = Trace(origin, direction, t_plain, n_plain, false);
    const HitType bounded = Trace(origin, direction, t_bounded, n_bounded, true);
    REQUIRE(plain == bounded);
    REQUIRE(t_plain == t_bounded);
    if (plain != HitType::Sky) {
      REQUIRE(n_plain == n_bounded);
    }
    ++hits[static_cast<int>(plain)];
  }
  // Every kind of hit was tried many times.
  CHECK(hits[0] > 1000);
  CHECK(hits[1] > 1000);
  CHECK(hits[2] > 1000);
}

TEST_CASE("Trace finds the same hit with the bound as without, for rays grazing a sphere",
          "[trace][bound]") {
  // Through a point at distance 1 - u (u < 1e-3) from a letter sphere's centre, in a
  // random direction: rays that only just touch the outer spheres, which a box a hair
  // too small would lose, and random rays almost never are.
  std::mt19937 engine(11);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> which(0, kLetterSphereCount - 1);
  int sphere_hits = 0;
  for (int i = 0; i < 20000; ++i) {
    glm::dvec3 direction(unit(engine), unit(engine), unit(engine));
    glm::dvec3 side(unit(engine), unit(engine), unit(engine));
    if (glm::length(direction) < 0.1 || glm::length(glm::cross(direction, side)) < 0.1) {
      continue;
    }
    direction = glm::normalize(direction);
    side = glm::normalize(glm::cross(direction, side));
    const glm::dvec3 touched = LetterSpheres()[static_cast<std::size_t>(which(engine))] +
                               side * (1 - 1e-3 * (unit(engine) + 1) / 2);
    const glm::dvec3 origin = touched - direction * 3.0;
    double t_plain = 0, t_bounded = 0;
    glm::dvec3 n_plain(9), n_bounded(9);
    const HitType plain = Trace(origin, direction, t_plain, n_plain, false);
    REQUIRE(Trace(origin, direction, t_bounded, n_bounded, true) == plain);
    REQUIRE(t_plain == t_bounded);
    sphere_hits += plain == HitType::Sphere;
  }
  CHECK(sphere_hits > 10000);
}
