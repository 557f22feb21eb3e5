#pragma once
// Random kinematic trees using every joint type, for algorithm cross-checks (K6),
// derivative and constraint tests, allocation tests; deterministic for a given seed.
//
// Body b is "body<b>" on joint "joint<b>"; joint kinds cycle fixed, revolute,
// prismatic, cylindrical, universal, spherical, free (b mod 7). Masses 0.5-3 kg, CoM
// within 0.5 m of the body origin, principal moments 0.5-1 kg m^2 about the CoM on
// random axes; joint frames at random rotations, within 1 m (parent side) and 0.3 m
// (child side) of the body origins; random unit joint axes. Gravity (0.3, -0.2, -9.81)
// m/s^2, world frame, tilted so that no algorithm can rely on it being along Z.
#include <random>

#include "kernel/model/model.hpp"

namespace heavesim::samples {

struct RandomTreeOptions {
  int bodies = 12;
  bool added_inertia = false;  // give every third body a random SPD added inertia
  bool joint_springs = true;   // springs/dampers on scalar joints
  bool chain = false;          // a serial chain instead of a random tree
  bool only_revolute = false;  // all joints revolute (benchmark chains)
  bool constraints = false;    // also loop joints of every kind, a distance, a coupler and the drivers
};

/// Draws the tree (and, with `options.constraints`, six loop joints, the distance
/// constraint "rod", the coupler "gear", the joint driver "push" on joint3, the absolute
/// driver "slide" on body2, the distance driver "stretch" from ground to the last body
/// and the angle driver "twist" from body1 to the last but one) from `random`.
Model random_tree(std::mt19937_64& random, const RandomTreeOptions& options);

/// A state for `model`: q = neutral + a tangent displacement with entries in
/// [-1.5, 1.5] (unit quaternions), v in [-2, 2] (rad/s, m/s), joint forces tau in
/// [-5, 5] (N m, N) and world-frame external spatial forces on every link ([moment
/// about the world origin, N m, entries within 3; force, N, within 10]).
struct RandomState {
  VectorX q, v, tau;
  AlignedVector<Force> external_forces;
};
RandomState random_state(const Model& model, std::mt19937_64& random);

/// A random tree of `bodies` bodies (options otherwise default; added inertia on every
/// third body when asked; a serial chain when asked) and a random state on it, drawn in
/// that order from `random`.
struct RandomTreeAndState {
  Model model;
  RandomState state;
};
RandomTreeAndState random_tree_and_state(std::mt19937_64& random, int bodies, bool added_inertia, bool chain = false);

}  // namespace heavesim::samples
