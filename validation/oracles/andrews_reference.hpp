#pragma once
// Andrews' squeezing mechanism (Hairer & Wanner, Solving Ordinary Differential
// Equations II, 2nd ed., 1996, §VII.7; IFToMM multibody benchmark A03): the published
// reference and the accuracy measure of the Test Set for IVP Solvers (F. Mazzia and
// C. Magherini, release 2.4, University of Bari and INdAM Bari unit, 2008, problem
// `andrews`, http://www.dm.uniba.it/~testset/). docs/physics/benchmarks.md.
//
// Coordinates, in the test set's order: beta, Theta, gamma, Phi, delta, Omega, epsilon
// [rad]. beta, gamma, delta, epsilon are absolute; Theta is relative to beta, Phi to
// delta, Omega to epsilon (cases/validation/iftomm_a03_andrews.yaml maps them to joints).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace heavesim::oracle {

/// The number of position coordinates (and of reference components).
inline constexpr int andrews_coordinates = 7;

/// The test set's consistent initial positions at t = 0 [rad] (velocities zero).
inline constexpr std::array<double, andrews_coordinates> andrews_initial_positions = {
    -0.0617138900142764496358948458001, 0.0, 0.455279819163070380255912382449, 0.222668390165885884674473185609,
    0.487364979543842550225598953530,   -0.222668390165885884674473185609, 1.23054744454982119249735015568};

/// The end of the test set's interval [s].
inline constexpr double andrews_end_time = 0.03;

/// The joints of cases/validation/iftomm_a03_andrews*.yaml in the test set's coordinate
/// order: each joint's coordinate is that angle.
inline constexpr std::array<const char*, andrews_coordinates> andrews_joint_names = {
    "beta", "Theta", "gamma", "Phi", "delta", "Omega", "epsilon"};

/// The test set's reference positions at t = 0.03 s [rad]: PSIDE with rtol = atol =
/// 1e-14 (Cray C90 double precision), as published in the problem's reference
/// solution. The angles beta and Theta have turned about 2.5 times.
inline constexpr std::array<double, andrews_coordinates> andrews_reference_positions = {
    0.1581077119629904e+2,  -0.1575637105984298e+2, 0.4082224013073101e-1, -0.5347301163226948e+0,
    0.5244099658805304e+0, 0.5347301163226948e+0,  0.1048080741042263e+1};

/// The test set's mixed error significant correct digits,
///   mescd = -log10( max_i |y_i - yref_i| / (atol/rtol + |yref_i|) ),
/// over the components it scores (for `andrews` the 7 positions; the test set's
/// report.f takes the maximum norm of the mixed relative-absolute error, each code
/// trying to keep it below rtol). `absolute_over_relative` is the run's atol/rtol; the
/// test set runs `andrews` with atol = rtol, i.e. 1. A zero error gives the digits of
/// the unit round-off (report.f replaces a zero maximum by it).
inline double mixed_error_significant_digits(const std::array<double, andrews_coordinates>& computed,
                                             const std::array<double, andrews_coordinates>& reference,
                                             double absolute_over_relative = 1.0) {
  double largest = 0.0;
  for (int i = 0; i < andrews_coordinates; ++i)
    largest = std::max(largest, std::abs(computed[i] - reference[i]) / (absolute_over_relative + std::abs(reference[i])));
  if (std::isnan(largest)) return -std::numeric_limits<double>::infinity();
  return -std::log10(std::max(largest, std::numeric_limits<double>::epsilon() / 2));
}

}  // namespace heavesim::oracle
