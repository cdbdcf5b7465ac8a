// The progress line of long renders (cgfs/progress.h).
#include <catch2/catch.hpp>

#include "cgfs/progress.h"

TEST_CASE("ProgressDisplay::Line: percentage and seconds, or seconds alone", "[progress]") {
  CHECK(cgfs::ProgressDisplay::Line("fig-5-1", 0.375, 2.25) == "rendering fig-5-1   38%  2.2 s");
  CHECK(cgfs::ProgressDisplay::Line("fig-5-1", -1, 1.5) == "rendering fig-5-1  1.5 s");
}
