#pragma once
// Closed kinematic loops: a parallelogram four-bar, a slider whose pendulum is
// tethered to the ground, and two rails welded to one block (over-constrained).
#include <memory>

#include "kernel/model/model.hpp"

namespace heavesim::samples {

/// A parallelogram four-bar in the world XY plane, all joints revolute about world Z,
/// no spring. Bodies "crank", "coupler", "rocker": uniform 1 kg, 1 m rods along their
/// frame's +x (CoM (0.5, 0, 0) m, inertia diag(0, 1/12, 1/12) kg m^2 about the CoM).
/// Tree joints: "pivot_a" ground-crank at the origin, "pin" crank-coupler at the
/// crank's (1, 0, 0), "pivot_b" ground-rocker at world (0, 1, 0). Revolute loop joint
/// "closure" between the coupler's (0, 1, 0) and the rocker's (1, 0, 0). q = [crank,
/// coupler relative, rocker] angles [rad]; on the loop, q = (a, -a, a) keeps the
/// coupler parallel to the ground link. Gravity 9.81 m/s^2 along world -Z (normal to
/// the plane of motion).
std::shared_ptr<const Model> parallelogram_four_bar();

/// A slider (1 kg, unit rotational inertia) on prismatic joint "rail" along world X
/// from the origin, and a 1 m rod (1 kg, CoM (0, 0, -0.5) m, inertia 0.1 kg m^2 about
/// each CoM axis) on revolute joint "pin" about Y at the slider's origin. Distance
/// constraint "tether": 1 m between the world origin and the rod's tip (0, 0, -1) m.
/// Driver "push" prescribes the rail x(t) = 1 + t [m]. The loop cannot close beyond
/// x = 2 m (t = 1 s). Gravity 9.81 m/s^2 along world -Z.
std::shared_ptr<const Model> tethered_slider_pendulum();

/// Two 1 kg rods "rod_a", "rod_b" (unit rotational inertia) on prismatic joints
/// "slide_a", "slide_b" along world Z at world x = -1 m and x = +1 m, and a 1 kg block
/// welded to rod_a by the fixed joint "weld_a" (block origin at x = 0) and to rod_b by
/// the fixed loop joint "weld_b": 6 constraint rows of rank 1 (5 redundant).
Model overconstrained_rails();

}  // namespace heavesim::samples
