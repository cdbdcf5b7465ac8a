// The build must not fuse a*b + c into a fused multiply-add: an FMA rounds once
// instead of twice, and then a pixel exactly on an edge can land on the other side
// on some machines (-march=native, aarch64) and not on others. CMakeLists.txt pins
// -ffp-contract=off for every target; this test fails if that is ever lost.
#include <catch2/catch.hpp>

TEST_CASE("a*b + c is rounded twice, not fused into one FMA", "[floating-point]") {
  // a*a = 1 + 2^-26 + 2^-54 exactly. Rounded to a double, the 2^-54 is lost, so
  // a*a + c is 0; an FMA keeps it and gives 2^-54. The volatile loads keep the
  // compiler from working it out while compiling.
  volatile double stored_a = 1 + 0x1p-27;
  volatile double stored_c = -(1 + 0x1p-26);
  const double a = stored_a;
  const double c = stored_c;
  CHECK(a * a + c == 0.0);
}
