#pragma once
// Random kinematic trees using every joint type, for algorithm cross-checks (K6),
// allocation tests and benchmarks; deterministic for a given seed.
#include <random>

#include "kernel/model/model.hpp"

namespace heavesim::validation {

struct RandomTreeOptions {
  int bodies = 12;
  bool added_inertia = false;  // give every third body a random SPD added inertia
  bool joint_springs = true;   // springs/dampers on scalar joints
  bool chain = false;          // a serial chain instead of a random tree
  bool only_revolute = false;  // all joints revolute (benchmark chains)
  bool constraints = false;    // also loop joints of every kind, a distance, a coupler and a driver
};

Model random_tree(std::mt19937_64& random, const RandomTreeOptions& options);

/// A state (q with unit quaternions, v), joint forces and external forces for `model`.
struct RandomState {
  VectorX q, v, tau;
  AlignedVector<Force> external_forces;
};
RandomState random_state(const Model& model, std::mt19937_64& random);

}  // namespace heavesim::validation
