// The shared command-line handling: numbers, sizes and unknown options.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "cgfs/command_line.h"

using cgfs::UsageError;

TEST_CASE("whole numbers in range are accepted, anything else is refused", "[cli]") {
  CHECK(cgfs::ParseInt("3", "--depth", 0, 10) == 3);
  CHECK_THROWS_WITH(cgfs::ParseInt("3x", "--depth", 0, 10), "--depth: '3x' is not a whole number");
  CHECK_THROWS_WITH(cgfs::ParseInt("", "--depth", 0, 10), "--depth: '' is not a whole number");
  CHECK_THROWS_WITH(cgfs::ParseInt("11", "--depth", 0, 10), "--depth: 11 is out of range 0..10");
  CHECK_THROWS_AS(cgfs::ParseInt("99999999999999", "--depth", 0, 10), UsageError);
  CHECK_THROWS_AS(cgfs::ParseInt("-1", "--depth", 0, 10), UsageError);
}

TEST_CASE("sizes are WIDTHxHEIGHT with even sides in range", "[cli]") {
  int width = 0;
  int height = 0;
  cgfs::ParseSize("640x480", "--size", 2, 4096, &width, &height);
  CHECK(width == 640);
  CHECK(height == 480);
  CHECK_THROWS_AS(cgfs::ParseSize("600", "--size", 2, 4096, &width, &height), UsageError);
  CHECK_THROWS_AS(cgfs::ParseSize("601x600", "--size", 2, 4096, &width, &height), UsageError);
  CHECK_THROWS_AS(cgfs::ParseSize("0x0", "--size", 2, 4096, &width, &height), UsageError);
  CHECK_THROWS_AS(cgfs::ParseSize("8192x8192", "--size", 2, 4096, &width, &height), UsageError);
}

TEST_CASE("options take values with a space or an equals sign", "[cli]") {
  int depth = 3;
  std::string output;
  bool list = false;
  cgfs::CommandLine command_line("test", "a test");
  command_line.AddInt("--depth", "N", "recursion depth", &depth, 0, 10);
  command_line.AddString("--output", "DIR", "output folder", &output);
  command_line.AddFlag("--list", "list", &list);
  const char* argv[] = {"test", "--depth=5", "--output", "somewhere", "--list"};
  CHECK(command_line.Parse(5, argv));
  CHECK(depth == 5);
  CHECK(output == "somewhere");
  CHECK(list);
}

TEST_CASE("unknown options, missing values and stray arguments are refused", "[cli]") {
  int depth = 3;
  cgfs::CommandLine command_line("test", "a test");
  command_line.AddInt("--depth", "N", "recursion depth", &depth, 0, 10);
  const char* unknown[] = {"test", "--colour"};
  CHECK_THROWS_WITH(command_line.Parse(2, unknown), "unknown option '--colour'");
  const char* missing[] = {"test", "--depth"};
  CHECK_THROWS_WITH(command_line.Parse(2, missing), "--depth needs a value (N)");
  const char* stray[] = {"test", "picture.png"};
  CHECK_THROWS_WITH(command_line.Parse(2, stray), "unexpected argument 'picture.png'");
  const char* short_option[] = {"test", "-x"};
  CHECK_THROWS_WITH(command_line.Parse(2, short_option), "unknown option '-x'");
}
