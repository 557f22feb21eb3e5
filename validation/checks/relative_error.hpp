#pragma once
// The relative error the kernel checks (K1, K2) report.
#include <algorithm>

#include "kernel/spatial/types.hpp"

namespace heavesim::validation {

/// Relative error ||a - b|| / max(||b||, floor).
inline double relative_error(const VectorX& a, const VectorX& b, double floor = 1e-12) {
  return (a - b).norm() / std::max(b.norm(), floor);
}

}  // namespace heavesim::validation
