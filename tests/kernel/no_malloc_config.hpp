#pragma once
// First in the precompiled header of the no-malloc test build (tests/CMakeLists.txt): makes
// Eigen's runtime allocation check active in optimized builds and turns a violation
// into an exception the test can see, instead of an abort.
#include <stdexcept>
#define EIGEN_RUNTIME_NO_MALLOC
#define eigen_assert(condition) \
  do {                          \
    if (!(condition)) throw std::runtime_error("Eigen assertion failed: " #condition); \
  } while (false)
