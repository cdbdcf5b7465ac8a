// Catch2's main(), compiled once for every test program.
#define CATCH_CONFIG_MAIN
// Wide enough that the paths of failure images are printed on one line.
#define CATCH_CONFIG_CONSOLE_WIDTH 160
#include <catch2/catch.hpp>
