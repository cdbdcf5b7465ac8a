# instrumentation/'s sources, for its library here and for the web pages' build
# (program/web): one list, so that neither misses a file.
set(CGFS_INSTRUMENTATION_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/src/progress.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/tally.cpp)
