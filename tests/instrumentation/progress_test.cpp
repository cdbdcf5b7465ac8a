// How far a figure's drawing has got (cgfs/progress.h): what a renderer reports is what
// the program that shows it reads, and a new figure starts with nothing reported.
#include <catch2/catch.hpp>

#include "cgfs/progress.h"

TEST_CASE("ReportProgress: the last fraction reported, -1 after ResetProgress", "[progress]") {
  cgfs::ResetProgress();
  CHECK(cgfs::ReportedProgress() == -1);
  cgfs::ReportProgress(0.25);
  cgfs::ReportProgress(0.5);
  CHECK(cgfs::ReportedProgress() == 0.5);
  cgfs::ResetProgress();
  CHECK(cgfs::ReportedProgress() == -1);
}
