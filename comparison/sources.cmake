# The comparison's sources, for its library here and for the web pages' build
# (program/web), which compiles them with emscripten.
set(CGFS_COMPARISON_SOURCES ${CMAKE_CURRENT_LIST_DIR}/src/compare.cpp)
