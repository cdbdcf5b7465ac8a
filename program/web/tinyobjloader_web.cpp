// tinyobjloader for the chapters' web pages: the native programs link Debian's library
// (its double-precision build, cmake/Dependencies.cmake); the page's build compiles the
// same library from the header Debian installs with it, with the same precision
// (TINYOBJLOADER_USE_DOUBLE, set in CMakeLists.txt), so that a model is read in the page
// as the native programs read it.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
