// Listing 5-1: the camera.
#include <catch2/catch.hpp>

#include "printing.h"
#include "scenes.h"
