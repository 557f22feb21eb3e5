#pragma once
// Hand statics of a spring-loaded crane (cases/statics/spring_crane.yaml), written from
// the free-body diagram of the boom, independently of the kernel: a boom of length L and
// mass m_b (CoM at L/2) elevated by theta about a horizontal pin at its foot, a payload
// m_p at its tip, a linear spring (k, rest length l0) from the boom at distance a to the
// mast head at height h above the foot. With e = (cos theta, 0, sin theta), P = a e,
// H = (0, 0, h), T = k (|H - P| - l0) the spring's tension, the moment about the pin
// (axis -y, positive raising the boom) is
//   M(theta) = T (P x (H - P) / |H - P|) . (-y) - (m_b L/2 + m_p L) g cos theta = 0,
// solved for theta by bisection on a bracket; the pin's reaction on the boom closes the
// force balance: R = (m_b + m_p) g z - T (H - P) / |H - P|.
#include <Eigen/Core>

namespace heavesim::oracle {

struct SpringCrane {
  double g = 9.81;           // m/s^2
  double boom_length = 20;   // m
  double boom_mass = 2000;   // kg
  double payload_mass = 5000;  // kg
  double spring_point = 12;  // m along the boom
  double mast_height = 15;   // m above the foot
  double stiffness = 1.5e4;  // N/m
  double rest_length = 6;    // m
};

struct SpringCraneEquilibrium {
  double elevation = 0.0;            // rad
  Eigen::Vector3d foot_reaction;     // N, ground on boom, world axes
  double spring_tension = 0.0;       // N
};

/// The elevation in (lower, upper) [rad] where M changes sign (the bracket must hold one).
SpringCraneEquilibrium spring_crane_equilibrium(const SpringCrane& crane, double lower, double upper);

/// M(theta) [N m] (above).
double spring_crane_moment(const SpringCrane& crane, double elevation);

}  // namespace heavesim::oracle
