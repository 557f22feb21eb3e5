#pragma once
// Oracle for validation A04 (IFToMM benchmark A04, Bricard's mechanism;
// docs/physics/benchmarks.md): the five rods as an open chain of revolute joints in their
// own coordinates x (the joint angles), with the sixth joint's five closure equations
// Phi(x) = 0 of which four are independent. Written apart from the kernel: rotation
// matrices instead of spatial algebra, body Jacobians (columns w_j x (r - o_j), w_j)
// instead of CRBA and RNEA, the mass matrix M = sum m Jv^T Jv + Jw^T I Jw, the velocity
// terms by central differences of M and J along x' (Lagrange: c = M' x' - 1/2 d(x'^T M x')/dx),
// and the redundant row handled by the null space of J from an SVD instead of a QR:
//   x'' = x''_p + N (N^T M N)^-1 N^T (Q - c - M x''_p),   x''_p = -J^+ (J' x'),
// N the one-dimensional null space of J. Integrated by ARKODE Fehlberg 8(7)
// (reference_integrator); the differences cost ~1e-10 of accuracy.
#include <Eigen/Core>
#include <vector>

namespace heavesim::oracle {

struct BricardSample {
  Eigen::Vector3d p3;             // m, the corner B between rods 2 and 3 (the benchmark's P3), world
  double energy = 0.0;            // J, kinetic + gravitational (gravity 9.81 along -y)
  double closure_residual = 0.0;  // max |Phi| (m or rad): the integration's drift off the loop
};

/// From rest at the benchmark's configuration (all joint angles 0), at each time [s]
/// (ascending, > 0).
std::vector<BricardSample> bricard_samples(const std::vector<double>& times, double tolerance);

}  // namespace heavesim::oracle
