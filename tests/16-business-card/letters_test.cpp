// The card's scene: the bitmap G of "aek" and the spheres it places.
#include <catch2/catch.hpp>

#include <bit>
#include <string>

#include "bound.h"
#include "checks.h"
#include "letters.h"

using cgfs::test::CheckNear;

TEST_CASE("the bitmap G spells aek, k = 18 on the left, j = 8 at the top", "[letters]") {
  // Drawn from the card's nine numbers by hand (each row's binary digits, highest
  // bit first, '#' for 1).
  const char* expected[9] = {
      "..............#....",  // j = 8: 16
      "..............#....",  // j = 7: 16
      ".###....###...#....",  // j = 6: 231184
      "....#..#...#..#...#",  // j = 5: 18577
      "....#..#...#..#..#.",  // j = 4: 18578
      ".####..#####..#.#..",  // j = 3: 249748
      "#...#..#......##...",  // j = 2: 280600
      "#...#..#......#.#..",  // j = 1: 280596
      ".####...###...#..#.",  // j = 0: 247570
  };
  for (int j = 8; j >= 0; --j) {
    std::string row;
    for (int k = 18; k >= 0; --k) {
      row += HasSphere(k, j) ? '#' : '.';
    }
    INFO("j = " << j);
    CHECK(row == expected[8 - j]);
  }
}

TEST_CASE("49 unit spheres at (k, 0, j + 4), in the card's order", "[letters]") {
  int bits = 0;
  for (std::uint32_t row : kLetterRows) {
    bits += std::popcount(row);
  }
  CHECK(bits == 49);
  CHECK(kLetterSphereCount == 49);
  // Bit 14 of G[4] = 18578 is set: the sphere at (14, 0, 8).
  CHECK(HasSphere(14, 4));
  CHECK_FALSE(HasSphere(13, 4));
  CheckNear(SphereCentre(14, 4), {14, 0, 8});
  // k from 18 down, j from 8 down: the first are (18, 0, 6) and (18, 0, 5), the
  // last (0, 0, 9).
  const auto& spheres = LetterSpheres();
  CheckNear(spheres[0], {18, 0, 6});
  CheckNear(spheres[1], {18, 0, 5});
  CheckNear(spheres[2], {17, 0, 10});
  CheckNear(spheres[48], {0, 0, 9});
}

TEST_CASE("the bound: one box per letter, a, e and k, holding every sphere once", "[bound]") {
  const auto& letters = LetterBounds();
  REQUIRE(letters.size() == 3);
  // "a": columns 18..14, 17 spheres, j 0..6; "e": 11..7, 17, j 0..6; "k": 4..0, 15, j 0..8.
  CHECK(letters[0].first == 0);
  CHECK(letters[0].count == 17);
  CHECK(letters[1].first == 17);
  CHECK(letters[1].count == 17);
  CHECK(letters[2].first == 34);
  CHECK(letters[2].count == 15);
  // The tight boxes around the unit spheres, worked out from the bitmap; each box holds
  // its tight box with a margin above 0 and below 0.01 on every side.
  const glm::dvec3 tight[3][2] = {
      {{13, -1, 3}, {19, 1, 11}}, {{6, -1, 3}, {12, 1, 11}}, {{-1, -1, 3}, {5, 1, 13}}};
  for (int letter = 0; letter < 3; ++letter) {
    for (int axis = 0; axis < 3; ++axis) {
      INFO("letter " << letter << ", axis " << axis);
      const Box& box = letters[static_cast<std::size_t>(letter)].box;
      CHECK(box.min[axis] < tight[letter][0][axis]);
      CHECK(box.min[axis] > tight[letter][0][axis] - 0.01);
      CHECK(box.max[axis] > tight[letter][1][axis]);
      CHECK(box.max[axis] < tight[letter][1][axis] + 0.01);
    }
  }
}

TEST_CASE("MayHit: the slab test of a ray against a box", "[bound]") {
  const Box box{{0, 0, 0}, {1, 1, 1}};
  CHECK(MayHit(box, {-1, 0.5, 0.5}, {1, 0, 0}, 1e9));           // straight through
  CHECK_FALSE(MayHit(box, {-1, 2, 0.5}, {1, 0, 0}, 1e9));       // beside it
  CHECK_FALSE(MayHit(box, {2, 0.5, 0.5}, {1, 0, 0}, 1e9));      // behind the ray
  CHECK_FALSE(MayHit(box, {-5, 0.5, 0.5}, {1, 0, 0}, 2));       // beyond the nearest hit so far
  CHECK(MayHit(box, {0.5, 0.5, 0.5}, {0, 0, 1}, 1e9));          // from inside
  CHECK_FALSE(MayHit(box, {0.5, 0.5, 1.005}, {0, 0, 1}, 1e9));  // leaving it: nothing past 0.01
  const glm::dvec3 diagonal = glm::normalize(glm::dvec3(1, 1, 1));
  CHECK(MayHit(box, {-1, -1, -1}, diagonal, 1e9));
  CHECK_FALSE(MayHit(box, {-1, -1, 2.5}, diagonal, 1e9));
}
