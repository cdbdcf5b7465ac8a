// "Depth Buffering" and "Using 1/Z Instead of Z": the buffer's initial value and
// comparison, the 1/z worked example, and depth-tested triangles. Chapters 13 to 15
// keep them and run these tests too.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "cases.h"
#include "printing.h"
#include "scenes.h"

using Catch::Detail::Approx;
using cgfs::test::IsSameImageAs;

TEST_CASE("DepthBuffer with 1/z starts at 0 and keeps what is strictly closer", "[depth]") {
  const Canvas canvas(600, 600);
  DepthBuffer buffer(canvas, DepthValue::kInverseZ);
  CHECK(buffer.At(10, 20) == 0);  // 1/infinity: any point in front of the camera is closer
  CHECK(buffer.DepthOf(4) == 0.25);
  CHECK(buffer.TestAndSet(10, 20, buffer.DepthOf(10)));
  CHECK(buffer.At(10, 20) == 0.1);
  CHECK_FALSE(buffer.TestAndSet(10, 20, buffer.DepthOf(20)));  // farther
  CHECK_FALSE(buffer.TestAndSet(10, 20, buffer.DepthOf(10)));  // as far: strictly closer only
  CHECK(buffer.At(10, 20) == 0.1);
  CHECK(buffer.TestAndSet(10, 20, buffer.DepthOf(5)));  // closer
  CHECK(buffer.At(10, 20) == 0.2);
  CHECK(buffer.At(11, 20) == 0);  // its neighbours are untouched
  CHECK(buffer.At(10, 21) == 0);
}

TEST_CASE("DepthBuffer with z starts at +infinity and keeps what is strictly closer", "[depth]") {
  const Canvas canvas(600, 600);
  DepthBuffer buffer(canvas, DepthValue::kZ);
  CHECK(buffer.At(-5, -7) == std::numeric_limits<double>::infinity());
  CHECK(buffer.DepthOf(4) == 4);
  CHECK(buffer.TestAndSet(-5, -7, 10));
  CHECK_FALSE(buffer.TestAndSet(-5, -7, 20));
  CHECK_FALSE(buffer.TestAndSet(-5, -7, 10));
  CHECK(buffer.TestAndSet(-5, -7, 5));
  CHECK(buffer.At(-5, -7) == 5);
}

TEST_CASE("DepthBuffer maps pixels as PutPixel does and ignores pixels off the canvas", "[depth]") {
  const Canvas canvas(600, 400);
  DepthBuffer buffer(canvas, DepthValue::kInverseZ);
  // The four corners of the canvas are four different cells.
  CHECK(buffer.TestAndSet(-300, -200, 0.1));
  CHECK(buffer.TestAndSet(299, -200, 0.2));
  CHECK(buffer.TestAndSet(-300, 199, 0.3));
  CHECK(buffer.TestAndSet(299, 199, 0.4));
  CHECK(buffer.At(-300, -200) == 0.1);
  CHECK(buffer.At(299, -200) == 0.2);
  CHECK(buffer.At(-300, 199) == 0.3);
  CHECK(buffer.At(299, 199) == 0.4);
  // Just off the canvas on every side: nothing to test, nothing to draw.
  CHECK_FALSE(buffer.TestAndSet(300, 0, 1));
  CHECK_FALSE(buffer.TestAndSet(-301, 0, 1));
  CHECK_FALSE(buffer.TestAndSet(0, 200, 1));
  CHECK_FALSE(buffer.TestAndSet(0, -201, 1));
}

TEST_CASE("z is not linear on the canvas, 1/z is: the book's worked example", "[depth]") {
  // A = (-1, 0, 2), B = (1, 0, 10), their midpoint M = (0, 0, 6), d = 1: A'x = -0.5,
  // B'x = 0.1 and M'x = 0 on the viewport, 600 pixels wide.
  const Canvas canvas(600, 600);
  const Viewport viewport;
  const Vec3 A(-1, 0, 2), B(1, 0, 10), C(-1, 0.5, 2);
  CHECK(ProjectVertex(A, canvas, viewport) == Point{-300, 0});
  CHECK(ProjectVertex(B, canvas, viewport) == Point{60, 0});
  CHECK(ProjectVertex({0, 0, 6}, canvas, viewport) == Point{0, 0});
  // A triangle whose bottom edge is AB, drawn into each kind of buffer: at M' the
  // z buffer holds 8.6667 (wrong), the 1/z buffer 0.166667, which is 1/6 (right).
  const auto stored_at_M = [&](DepthValue value) {
    Canvas drawn(600, 600);
    DepthBuffer buffer(drawn, value);
    DrawFilledTriangle(ProjectVertex(A, drawn, viewport), ProjectVertex(B, drawn, viewport),
                       ProjectVertex(C, drawn, viewport), A.z, B.z, C.z, cgfs::kRed, drawn, buffer);
    return buffer.At(0, 0);
  };
  CHECK(stored_at_M(DepthValue::kZ) == Approx(8.666667));
  CHECK(stored_at_M(DepthValue::kInverseZ) == Approx(0.166667));
  CHECK(1 / stored_at_M(DepthValue::kInverseZ) == Approx(6));
}

TEST_CASE("inside a triangle the 1/z buffer holds the plane's 1/z, the z buffer does not",
          "[depth]") {
  // A triangle of the plane z = 4 + 3x, from z = 1 to z = 10: what each buffer holds
  // at a pixel, against the true depth of the point that pixel shows.
  const Vec3 V0(-1, -2, 1), V1(2, 0, 10), V2(-1, 2, 1);
  const auto true_z = [](int x) {
    // The ray through canvas column x (viewport x' = x/600, d = 1) meets z = 4 + 3x at
    // z = 4 / (1 - 3x').
    return 4 / (1 - 3 * (x / 600.0));
  };
  for (const DepthValue value : {DepthValue::kInverseZ, DepthValue::kZ}) {
    Canvas canvas(600, 600);
    DepthBuffer buffer(canvas, value);
    const Viewport viewport;
    DrawFilledTriangle(ProjectVertex(V0, canvas, viewport), ProjectVertex(V1, canvas, viewport),
                       ProjectVertex(V2, canvas, viewport), V0.z, V1.z, V2.z, cgfs::kRed, canvas,
                       buffer);
    double worst = 0;
    for (int x = -290; x <= 90; x += 20) {
      const double stored = buffer.At(x, 0);
      const double z = value == DepthValue::kZ ? stored : 1 / stored;
      worst = std::max(worst, std::abs(z - true_z(x)) / true_z(x));
    }
    if (value == DepthValue::kInverseZ) {
      CHECK(worst < 0.01);  // only the rounding of the vertices to whole pixels
    } else {
      CHECK(worst > 0.5);  // far off in the middle of the triangle
    }
  }
}

TEST_CASE("a depth-tested triangle on an empty buffer covers what DrawFilledTriangle covers",
          "[depth]") {
  Canvas plain(600, 600);
  DrawFilledTriangle({-200, -250, 1}, {200, 50, 1}, {20, 250, 1}, cgfs::kGreen, plain);
  Canvas tested(600, 600);
  DepthBuffer buffer(tested, DepthValue::kInverseZ);
  DrawFilledTriangle({-200, -250, 1}, {200, 50, 1}, {20, 250, 1}, 3, 7, 5, cgfs::kGreen, tested,
                     buffer);
  CHECK_THAT(tested.GetImage(), IsSameImageAs(plain.GetImage()));
}

TEST_CASE("DrawFilledTriangle with a depth buffer: the cases of 12-hidden-surface-removal.json",
          "[depth]") {
  using cgfs::test::ToNumber;
  const auto point = [](const nlohmann::json& P) {
    return Point{static_cast<int>(ToNumber(P.at(0))), static_cast<int>(ToNumber(P.at(1)))};
  };
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("12-hidden-surface-removal.json", "DrawFilledTriangle")) {
    INFO(c.Describe());
    const nlohmann::json& size = c.given.at("canvas");
    Canvas canvas(size.at("width").get<int>(), size.at("height").get<int>(),
                  cgfs::test::kCaseBackground);
    DepthBuffer depth_buffer(canvas, DepthValue::kInverseZ);
    for (const nlohmann::json& call : c.calls) {  // in order, on one canvas and one buffer
      DrawFilledTriangle(point(call.at("P0")), point(call.at("P1")), point(call.at("P2")),
                         ToNumber(call.at("z0")), ToNumber(call.at("z1")), ToNumber(call.at("z2")),
                         cgfs::test::ToColor(call.at("color")), canvas, depth_buffer);
    }
    CHECK_THAT(cgfs::test::DrawnPixelsAsNumbers(canvas), cgfs::test::MatchesCase(c));
  }
}
