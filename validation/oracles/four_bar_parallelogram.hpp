#pragma once
// Oracle for validations L2 and A02: IFToMM benchmark A02, the N-four-bar (N windows, N + 1
// vertical cranks of length 1 m and N couplers, every rod 1 kg, 1 m, uniform). On the
// parallelogram branch every crank turns by the same angle q from upright and the
// couplers only translate, so the mechanism has one coordinate and Lagrange gives
//   q'' = g sin q ((N + 1)/2 + N) / ((N + 1)/3 + N),   q(0) = 0, q'(0) = 1 rad/s
// (kinetic energy (N+1) q'^2/6 of the cranks about their pivots plus N q'^2/2 of the
// translating couplers; potential g cos q ((N+1)/2 + N)). Integrated by ARKODE
// Fehlberg 8(7): it shares nothing with the multibody model. The same idea for any
// parallelogram linkage (validation L5) is parallelogram_crank_angles.
#include <vector>

namespace heavesim::oracle {

/// The crank angle q [rad] at each time [s] (ascending, > 0), for N windows and
/// gravity g [m/s^2].
std::vector<double> four_bar_crank_angles(int windows, double gravity, const std::vector<double>& times,
                                          double tolerance);

/// The same one-coordinate motion for any parallelogram linkage on its parallelogram
/// branch (validation L5: cranks hanging, a third crank parallel to the others): q is
/// every crank's angle from the downward vertical, the bars joining the crank tips only
/// translate, and Lagrange gives
///   q'' = -g sin q (first moment) / (second moment),
/// first moment = sum over cranks of m c + sum over translating bars of m L [kg m],
/// second moment = sum over cranks of I about the pivot + sum over translating bars of
/// m L^2 [kg m^2] (L the crank length, c a crank's centre of mass from its pivot).
/// The angle q [rad] at each time [s] (ascending, > 0) from q(0) = q0, q'(0) = rate0.
std::vector<double> parallelogram_crank_angles(double first_moment, double second_moment, double gravity,
                                               double q0, double rate0, const std::vector<double>& times,
                                               double tolerance);

}  // namespace heavesim::oracle
