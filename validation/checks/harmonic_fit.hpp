#pragma once
// Steady response at one frequency (the least-squares fit of signal/harmonic_fit.hpp)
// and the crossing period of a decay record, where a record is compared with a
// frequency-domain response after its ramp (validation H4, the hydro response tests).
#include <cmath>
#include <complex>
#include <vector>

#include "signal/harmonic_fit.hpp"

namespace heavesim::validation {

/// The complex amplitude X of the w component of x(times): signal/harmonic_fit.hpp,
/// the one fit shared with `heavesim rao`.
using stats::fit_harmonic;

/// Mean period [s] of an oscillating record from its zero crossings (linearly
/// interpolated between samples): twice the mean spacing of the crossings; 0 with fewer
/// than three crossings. Used for free-decay periods (hydro cases).
inline double crossing_period(const std::vector<double>& times, const std::vector<double>& x) {
  std::vector<double> crossings;
  for (std::size_t k = 1; k < x.size(); ++k)
    if ((x[k - 1] > 0) != (x[k] > 0)) crossings.push_back(times[k - 1] - x[k - 1] * (times[k] - times[k - 1]) / (x[k] - x[k - 1]));
  if (crossings.size() < 3) return 0.0;
  return 2.0 * (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

}  // namespace heavesim::validation
