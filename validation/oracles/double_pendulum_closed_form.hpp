#pragma once
// Textbook closed form of a general double pendulum in RELATIVE angles (the kernel's
// own coordinates), written out term by term: the 2x2 mass matrix, Coriolis and
// gravity terms from the Lagrangian, and the two pin reactions from Newton's law on
// each link's centre of mass. Used by validation K1.
//
// Geometry: pin 1 at the origin, rotation about +Y; link k hangs along
// (-sin phi_k, -cos phi_k) in (x, z) with absolute angle phi_1 = q1, phi_2 = q1 + q2.
#include <Eigen/Dense>

namespace heavesim::oracle {

struct DoublePendulumParameters {
  double m1, m2;      // kg
  double L1;          // m, pin-to-pin length of link 1
  double a1, a2;      // m, CoM distances from each link's upper pin
  double I1, I2;      // kg m^2 about each CoM
  double g = 9.81;    // m/s^2
};

struct DoublePendulumSolution {
  Eigen::Vector2d qdd;           // rad/s^2, relative joint accelerations
  Eigen::Vector2d pin1_force;    // N, (x, z): force of ground on link 1
  Eigen::Vector2d pin2_force;    // N, (x, z): force of link 1 on link 2
};

DoublePendulumSolution solve_double_pendulum(const DoublePendulumParameters& p, const Eigen::Vector2d& q,
                                             const Eigen::Vector2d& qd, const Eigen::Vector2d& tau);

}  // namespace heavesim::oracle
