#pragma once
// Oracle for validation A01 (IFToMM benchmark A01, docs/physics/benchmarks.md): the
// exact large-amplitude motion of a point-mass pendulum released at rest. With theta the
// angle from the downward vertical and theta(0) = theta0, theta'(0) = 0, energy gives
//   sin(theta/2) = k sn(K(k) - w0 t, k),   k = sin(theta0 / 2),   w0 = sqrt(g / L)
// (Lawden, Elliptic Functions and Applications, 1989, §5.2; Abramowitz & Stegun 16.1).
// sn and K come from the arithmetic-geometric mean (descending Landen transformation,
// Abramowitz & Stegun 16.4 and 17.6): no integration, no kernel code.
#include <Eigen/Core>
#include <vector>

namespace heavesim::oracle {

/// Jacobi sn(u | m), cn(u | m) for parameter m = k^2 in [0, 1), by the AGM scale
/// (A&S 16.4.3): good to a few 1e-16 relative of the period over any |u|.
struct JacobiSnCn {
  double sn = 0.0;
  double cn = 1.0;
};
JacobiSnCn jacobi_sn_cn(double u, double parameter_m);

/// The complete elliptic integral of the first kind K(m) = pi / (2 AGM(1, sqrt(1 - m))).
double complete_elliptic_integral_k(double parameter_m);

/// theta(t) [rad] from the downward vertical (positive towards +x), released at rest at
/// theta0 in (0, pi) [rad], pendulum of length L [m] under gravity g [m/s^2].
double pendulum_angle(double theta0, double length, double gravity, double time);

/// The point mass in the plane of motion [m] at each time: (L sin theta, -L cos theta),
/// pivot at the origin, gravity along -y.
std::vector<Eigen::Vector2d> pendulum_mass_positions(double theta0, double length, double gravity,
                                                     const std::vector<double>& times);

}  // namespace heavesim::oracle
