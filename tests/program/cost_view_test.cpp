// Counts per pixel as a picture (program/cost_view.h).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "program/cost_view.h"
#include "program/figure.h"

using cgfs::Canvas;
using cgfs::CostRamp;
using cgfs::Rgb8;

namespace {

// The brightness Green's ramp is built to rise in (his weights 0.30, 0.59, 0.11):
// what a grey print of the colour shows.
double Luma(Rgb8 c) {
  return 0.30 * c.r + 0.59 * c.g + 0.11 * c.b;
}

}  // namespace

TEST_CASE("the ramp runs from black to white, its brightness rising all the way", "[cost]") {
  CHECK(CostRamp(0) == Rgb8{0, 0, 0});
  CHECK(CostRamp(1) == Rgb8{255, 255, 255});
  CHECK(CostRamp(-3) == CostRamp(0));
  CHECK(CostRamp(7) == CostRamp(1));
  // Green's cubehelix at a quarter: a dark blue-green, worked by hand from his equation
  // 2 (phi = 2 pi (1/6 - 3/8), a = 3/32): r = 0.25 + a (-0.14861 cos phi + 1.78277 sin phi)...
  const double phi = 2 * M_PI * (0.5 / 3 - 1.5 * 0.25), a = 0.25 * 0.75 / 2;
  const Rgb8 quarter = CostRamp(0.25);
  CHECK(quarter.r == std::lround(255 * (0.25 + a * (-0.14861 * cos(phi) + 1.78277 * sin(phi)))));
  CHECK(quarter.g == std::lround(255 * (0.25 + a * (-0.29227 * cos(phi) - 0.90649 * sin(phi)))));
  CHECK(quarter.b == std::lround(255 * (0.25 + a * 1.97294 * cos(phi))));
  // Steps of two grey levels: more than the rounding to 8 bits can take back.
  double previous = -1;
  for (int i = 0; i <= 128; ++i) {
    const double luma = Luma(CostRamp(i / 128.0));
    INFO("position " << i / 128.0);
    CHECK(luma > previous);
    previous = luma;
  }
}

TEST_CASE("counts sit on the ramp on a log scale up to the scale's top", "[cost]") {
  CHECK(cgfs::CostPosition(0, 100) == 0);
  CHECK(cgfs::CostPosition(100, 100) == 1);
  CHECK(cgfs::CostPosition(1000, 100) == 1);
  CHECK(cgfs::CostPosition(9, 99) == Approx(0.5));  // ln 10 / ln 100
  CHECK(cgfs::CostPosition(0, 0) == 0);
  CHECK(cgfs::CostPosition(1, 0) == 1);
}

TEST_CASE("DrawCost draws each pixel's count and a strip with the scale", "[cost]") {
  Canvas canvas(50, 100);
  std::vector<cgfs::Count> counts(50 * 100, 0);
  counts[0] = 4;            // top-left pixel
  counts[50 * 10 + 7] = 2;  // column 7, row 10
  cgfs::DrawCost(canvas, counts, 4);
  const cgfs::Image& image = canvas.GetImage();
  CHECK(image.At(0, 0) == CostRamp(1));
  CHECK(image.At(7, 10) == CostRamp(std::log(3.0) / std::log(5.0)));
  CHECK(image.At(1, 0) == Rgb8{0, 0, 0});
  const int strip = cgfs::CostStripHeight(100);
  CHECK(strip == 4);
  CHECK(image.At(20, 100 - strip - 1) == Rgb8{255, 255, 255});
  // Five steps, 0 to 4, in blocks of 10 columns.
  for (int step = 0; step <= 4; ++step) {
    INFO("step " << step);
    const Rgb8 expected = CostRamp(cgfs::CostPosition(step, 4));
    CHECK(image.At(step * 10, 99) == expected);
    CHECK(image.At(step * 10 + 9, 100 - strip) == expected);
  }
  CHECK_THROWS_AS(cgfs::DrawCost(canvas, std::vector<cgfs::Count>(7), 4), std::invalid_argument);
  counts[1] = -1;  // nothing to count there
  cgfs::DrawCost(canvas, counts, 4);
  CHECK(canvas.GetImage().At(1, 0) == cgfs::kCostNothing);
  // A grey the ramp never takes: its hue is strongest halfway, where its brightness is.
  int near_grey = 0;
  for (int i = 0; i <= 1000; ++i) {
    const Rgb8 c = CostRamp(i / 1000.0);
    near_grey += std::max({std::abs(c.r - 128), std::abs(c.g - 128), std::abs(c.b - 128)}) <= 8;
  }
  CHECK(near_grey == 0);
}

TEST_CASE("above kCostStepsMax the strip runs smoothly from black to white", "[cost]") {
  Canvas canvas(40, 40);
  cgfs::DrawCost(canvas, std::vector<cgfs::Count>(40 * 40, 17), 1000);
  const cgfs::Image& image = canvas.GetImage();
  CHECK(image.At(0, 39) == Rgb8{0, 0, 0});
  CHECK(image.At(39, 39) == Rgb8{255, 255, 255});
  CHECK(image.At(3, 3) == CostRamp(std::log(18.0) / std::log(1001.0)));
}

TEST_CASE("CostPartner: a figure's cost view, and back, by name wherever it stands", "[cost]") {
  cgfs::Figure plain{"plain", "", {}}, costly{"costly", "", {}}, view{"costly-view", "", {}};
  costly.cost_view = "costly-view";
  const std::vector<const cgfs::Figure*> figures = {&view, &plain, &costly};
  CHECK(cgfs::CostPartner(figures, 2) == 0);             // costly: its view
  CHECK(cgfs::CostPartner(figures, 0) == 2);             // the view: back to costly
  CHECK(cgfs::CostPartner(figures, 1) == -1);            // plain has none
  CHECK(cgfs::CostPartner({&costly, &plain}, 0) == -1);  // its view not in the list
}

TEST_CASE("SetCostView pairs two figures by name, and refuses a name the list lacks", "[cost]") {
  std::vector<cgfs::Figure> figures = {{"a", "", {}}, {"a-view", "", {}}};
  cgfs::SetCostView(figures, "a", "a-view");
  CHECK(figures[0].cost_view == "a-view");
  CHECK_THROWS_AS(cgfs::SetCostView(figures, "a", "b-view"), std::logic_error);
  CHECK_THROWS_AS(cgfs::SetCostView(figures, "b", "a-view"), std::logic_error);
}
