# common/'s sources, for its library here and for the web pages' build (program/web),
# which compiles them with emscripten: one list, so that neither misses a file.
set(CGFS_COMMON_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/src/canvas.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/image.cpp)
