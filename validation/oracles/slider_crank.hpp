#pragma once
// Oracle for validation L1: the slider-crank of SUNDIALS' idaSlCrank_dns example,
// written here in one minimal coordinate (the crank angle theta) instead of the
// example's three coordinates and index-2 DAE. The rod angle phi and the slider
// position x follow in closed form on the branch cos(phi) > 0:
//   sin(phi) = -a sin(theta),   x = a cos(theta) + cos(phi),
// and the equation of motion is Lagrange's in theta,
//   B^T M (B theta'' + B' theta'^2) = B^T Q(s, s'),   s = (theta, x, phi), B = ds/dtheta,
// with M = diag(J1, m2, J2) and Q the generalized forces of the spring-damper between
// the crank and rod midpoints and of the horizontal push on the rod line.
#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

namespace heavesim::oracle {

struct SliderCrankParameters {
  double a = 0.5;   // m, crank length
  double J1 = 1.0;  // kg m^2, crank about its pivot
  double m2 = 1.0;  // kg, rod (its centre of mass on the slider pin)
  double J2 = 2.0;  // kg m^2, rod about the slider pin
  double k = 1.0, c = 1.0, l0 = 1.0;  // spring-damper: N/m, N s/m, m
  double F = 1.0;                     // N, horizontal push
};

/// (theta, x, phi) at each time, from theta(0) = pi/2, theta'(0) = 0; ARKODE Fehlberg 8(7).
std::vector<Eigen::Vector3d> slider_crank_positions(const SliderCrankParameters& p, const std::vector<double>& times,
                                                    double tolerance);

/// The rows "t y1 y2 y3 nst k h" of idaSlCrank_dns's printed output (the file the
/// example writes to standard output): (t, (theta, x, phi)); other lines are skipped.
std::vector<std::pair<double, Eigen::Vector3d>> read_ida_slider_crank_printout(const std::string& path);

}  // namespace heavesim::oracle
