#pragma once
// First in every source of the checked (sanitizer) build, through the precompiled
// header or -include (top CMakeLists.txt): makes Eigen's runtime allocation check and
// its assertions active in an optimized build with NDEBUG, and turns a violation into
// an exception a test can see, instead of an abort.
#include <stdexcept>
#define EIGEN_RUNTIME_NO_MALLOC
#define eigen_assert(condition) \
  do {                          \
    if (!(condition)) throw std::runtime_error("Eigen assertion failed: " #condition); \
  } while (false)
