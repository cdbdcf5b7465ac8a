// The progress line of long renders (program/progress_display.h).
#include <catch2/catch.hpp>

#include "program/progress_display.h"

TEST_CASE("ProgressDisplay::Line: percentage and seconds, or seconds alone", "[progress]") {
  CHECK(cgfs::ProgressDisplay::Line("fig-5-1", 0.375, 2.25) == "rendering fig-5-1   38%  2.2 s");
  CHECK(cgfs::ProgressDisplay::Line("fig-5-1", -1, 1.5) == "rendering fig-5-1  1.5 s");
}
