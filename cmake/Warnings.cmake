# Warnings on for everything we compile; clean under gcc and clang.
add_library(cgfs_warnings INTERFACE)
target_compile_options(cgfs_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
  -Wno-sign-conversion)
