# Every dependency is a Debian package; a missing one stops the configure step
# with one line naming the package (scripts/setup installs them all).

function(cgfs_require_package found package what)
  if(NOT ${found})
    message(FATAL_ERROR "${what} not found: install the Debian package '${package}' (or run scripts/setup)")
  endif()
endfunction()

find_package(glm QUIET CONFIG)
cgfs_require_package(glm_FOUND libglm-dev "GLM")

find_package(CLI11 QUIET CONFIG)
cgfs_require_package(CLI11_FOUND libcli11-dev "CLI11")

# Chapter 5 draws with several threads ("Parallelism").
find_package(Threads REQUIRED)

find_package(PkgConfig QUIET)
cgfs_require_package(PKG_CONFIG_FOUND pkgconf "pkg-config")
pkg_check_modules(STB QUIET IMPORTED_TARGET stb)
cgfs_require_package(STB_FOUND libstb-dev "stb (stb_image_write)")

# Untrusted images (students' figures, --texture files, --report folders) are read by
# decoders made for them, under continuous fuzzing: libpng and libjpeg-turbo.
find_package(PNG QUIET)
cgfs_require_package(PNG_FOUND libpng-dev "libpng")
find_package(JPEG QUIET)
cgfs_require_package(JPEG_FOUND libjpeg-dev "libjpeg (libjpeg-turbo)")

# Models (--model FILE.obj, program/src/model_file.cpp): Wavefront OBJ files read by
# tinyobjloader, in its double-precision build.
find_package(tinyobjloader QUIET CONFIG)
cgfs_require_package(tinyobjloader_FOUND libtinyobjloader-dev "tinyobjloader")

# --window (program/src/window.cpp): optional, so that a build without a display
# library still builds every chapter; without it --window says how to get it.
pkg_check_modules(SDL2 QUIET IMPORTED_TARGET sdl2)
if(NOT SDL2_FOUND)
  message(STATUS "SDL2 not found (Debian libsdl2-dev): the chapters build without --window")
endif()

if(CGFS_BUILD_TESTS)
  find_package(Catch2 2 QUIET CONFIG)
  cgfs_require_package(Catch2_FOUND catch2 "Catch2 v2")
  # The function cases (tests/cases/*.json), which the equation tests share with the
  # runners for other languages (tools/check-functions).
  find_package(nlohmann_json 3 QUIET CONFIG)
  cgfs_require_package(nlohmann_json_FOUND nlohmann-json3-dev "nlohmann/json")
endif()
