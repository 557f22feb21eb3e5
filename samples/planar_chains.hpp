#pragma once
// Planar pendulums and chains of links hanging from a ground pin.
//
// Geometry (all of them): revolute joints about world +Y; at q = 0 every link hangs
// straight down along world -Z; link i's frame is its joint frame at its upper pin, so
// link i + 1's pin is at (0, 0, -length_i) in link i's frame. Coordinates are RELATIVE
// angles q_i = theta_i - theta_{i-1} [rad] (theta = absolute angle from the downward
// vertical, positive about +Y). Gravity along world -Z.
#include <vector>

#include "kernel/model/model.hpp"

namespace heavesim::samples {

/// One link of a planar chain (the data a planar-chain oracle is written in).
struct PlanarLink {
  double length;   // m, pin to pin
  double mass;     // kg
  double com;      // m, CoM distance from the upper pin, along the link (down at q = 0)
  double inertia;  // kg m^2, about the CoM, about the pin axis (and the other transverse axis)
};

/// Bodies "link1".."linkN" on joints "pin1".."pinN" (two links: the double pendulum of
/// validation K1). Each link is a slender rod: its
/// inertia about the CoM is diag(inertia, inertia, 0) in the link frame (nothing
/// about the rod's own axis), CoM at (0, 0, -com).
Model planar_chain(const std::vector<PlanarLink>& links, double gravity = 9.81);

/// A single pendulum: body "rod" on joint "pin" about world +Y at the world origin,
/// CoM at (0, 0, -com_distance) [m], inertia about the CoM diag(inertia_about_com,
/// inertia_about_com, 0) [kg m^2], mass [kg]; gravity 9.81 m/s^2 along -Z.
Model pendulum(double mass, double com_distance, double inertia_about_com);

/// Relative joint angles q_i = theta_i - theta_{i-1} from absolute ones [rad], and back.
VectorX relative_from_absolute(const VectorX& theta);
VectorX absolute_from_relative(const VectorX& q);

}  // namespace heavesim::samples
