#pragma once
// The benchmark models, described once and built for every code that is compared:
// heavesim (to_model here), MuJoCo and DART (bench/) see identical trees.
//
// Every link frame is its parent's frame translated by `offset` (no rotation at
// q = 0); a revolute axis is given in that frame. Inertia is about the CoM, link axes.
// Gravity 9.81 m/s^2 along world -Z.
#include <string>
#include <vector>

#include "kernel/model/model.hpp"

namespace heavesim::samples {

struct BenchLink {
  int parent = -1;  // index of the parent link, -1 = ground
  bool free = false;
  Vector3 offset = Vector3::Zero();  // m, joint origin in the parent link frame
  Vector3 axis = Vector3::UnitY();   // revolute axis
  double mass = 1.0;                 // kg
  Vector3 com = Vector3::Zero();     // m, in the link frame
  Vector3 inertia = Vector3::Ones(); // kg m^2, principal moments about the CoM (link axes)
};

struct BenchModel {
  std::string name;
  std::vector<BenchLink> links;
};

/// 2 DoF: uniform 1 m, 1 kg rods about Y (the validation V2/V3 pendulum).
BenchModel bench_double_pendulum();
/// 7 DoF: a serial arm with alternating joint axes Z, Y, X (KUKA-like size).
BenchModel chain7();
/// 32 DoF: a free-floating torso with two 6-DoF legs and two 7-DoF arms.
BenchModel humanoid32();
/// 32 DoF: the same limbs and a 5-joint neck, 32 revolute joints on a fixed base.
BenchModel tree32_fixed();

/// The heavesim model of a description: bodies "link<i>" on joints "joint<i>"
/// (revolute about `axis`, or free), in the description's order.
Model to_model(const BenchModel& model);

/// `count` random states of `model`: q (a random displacement from neutral, unit
/// quaternions), v and tau with entries in [-1, 1] (SI); deterministic for a seed.
struct BenchStates {
  std::vector<VectorX> q, v, tau;
};
BenchStates bench_states(const Model& model, int count, unsigned seed);

}  // namespace heavesim::samples
