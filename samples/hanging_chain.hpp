#pragma once
// A chain of boxes hanging straight down from the world origin, joints alternating
// revolute (about the joint frame's x = world X) and spherical.
#include <vector>

#include "kernel/model/model.hpp"

namespace heavesim::samples {

/// Bodies "b0".."b{n-1}" with masses [kg] `masses`, each with its CoM 0.5 m below its
/// joint ((0, 0, -0.5) in its frame) and inertia diag(0.2, 0.3, 0.25) kg m^2 about
/// the CoM. Joint "j0" (revolute about X) at the world origin; joint "j{i}" at
/// (0, 0, -1) m in body i - 1's frame, spherical for odd i, revolute about X for even
/// i. At the neutral configuration every CoM is straight below its joint. Gravity
/// 9.81 m/s^2 along world -Z.
Model hanging_chain(const std::vector<double>& masses);

}  // namespace heavesim::samples
