// The card's camera vectors, and its random numbers.
#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include "camera.h"
#include "checks.h"
#include "random.h"

using cgfs::test::CheckNear;

TEST_CASE("MakeCamera(512, 512): the card's g, a, b and c", "[camera]") {
  const Camera camera = MakeCamera(512, 512);
  // g = (-6, -16, 0) / sqrt(292); a = (0, 0, 1) x g normalised, times 0.002.
  CheckNear(camera.g, {-0.351123, -0.936329, 0});
  CheckNear(camera.a, {0.00187266, -0.00070225, 0}, 1e-8);
  CheckNear(camera.b, {0, 0, 0.002}, 1e-12);
  CheckNear(camera.c, {-0.830524, -0.756554, -0.512});
  CHECK(camera.aperture == 99);
  // a points to +x, the image's left; the middle pixel's ray, 256a + 256b + c, is g.
  CheckNear(camera.a * 256.0 + camera.b * 256.0 + camera.c, camera.g, 1e-12);
  // The focal point of the middle pixel: the eye plus 16 g, just in front of the letters.
  CheckNear(kEye + camera.g * kFocus, {11.382, 1.018736, 8}, 1e-3);
}

TEST_CASE("MakeCamera: another size sees the same view through the same lens", "[camera]") {
  const Camera card = MakeCamera(512, 512);
  const Camera small = MakeCamera(256, 256);
  CheckNear(small.a, card.a * 2.0, 1e-12);
  CheckNear(small.c, card.c, 1e-12);
  // The lens is the same size: aperture times step.
  CHECK(small.aperture * glm::length(small.a) == Approx(card.aperture * glm::length(card.a)));
}

TEST_CASE("MakeCamera from a view: the eye moved along the image's axes, then turned", "[camera]") {
  const Camera card = MakeCamera(512, 512);
  CHECK(card.eye == kEye);
  // The image's right is -a normalised, (-0.936329, 0.351123, 0); its up +z; its
  // forward g.
  CheckNear(MakeCamera(512, 512, {{1, 0, 0}, 0, 0}).eye, kEye + glm::dvec3(-0.936329, 0.351123, 0));
  CheckNear(MakeCamera(512, 512, {{0, 1, 0}, 0, 0}).eye, kEye + glm::dvec3(0, 0, 1));
  CheckNear(MakeCamera(512, 512, {{0, 0, 2}, 0, 0}).eye, kEye + card.g * 2.0);
  // Turned 90 degrees to the left, it looks along a (the image's left) and its a points
  // back; 90 degrees up, it looks along b, straight up.
  const Camera left = MakeCamera(512, 512, {{0, 0, 0}, 90, 0});
  CheckNear(left.g, glm::normalize(card.a), 1e-12);
  CheckNear(left.a, -card.g * 0.002, 1e-12);
  CheckNear(MakeCamera(512, 512, {{0, 0, 0}, 0, 90}).g, {0, 0, 1}, 1e-12);
  // Turning keeps the middle pixel's ray on g, and the pixel steps at right angles.
  const Camera turned = MakeCamera(512, 512, {{0, 0, 0}, 30, -20});
  CheckNear(turned.a * 256.0 + turned.b * 256.0 + turned.c, turned.g, 1e-12);
  CHECK(glm::dot(turned.a, turned.b) == Approx(0).margin(1e-15));
  CHECK(glm::length(turned.g) == Approx(1));
}

TEST_CASE("Random: every pixel has its own numbers, the same every time", "[random]") {
  Random a(1, 10, 20), again(1, 10, 20), right(1, 11, 20), above(1, 10, 21), other(2, 10, 20);
  double sum = 0;
  for (int i = 0; i < 1000; ++i) {
    const double value = a.Rand();
    CHECK(value == again.Rand());
    CHECK(value >= 0);
    CHECK(value < 1);
    sum += value;
  }
  CHECK(sum / 1000 == Approx(0.5).margin(0.03));
  Random first(1, 10, 20);
  const double x = first.Rand();
  CHECK(right.Rand() != x);
  CHECK(above.Rand() != x);
  CHECK(other.Rand() != x);
}
