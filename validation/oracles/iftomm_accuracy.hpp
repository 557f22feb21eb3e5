#pragma once
// The accuracy measure of the IFToMM multibody benchmark library (iftomm-multibody.org,
// group A; González, Lugrís, Gutiérrez, Cuadrado, "A benchmarking system for MBS
// simulation software", Multibody System Dynamics 16 (2006)): a run is compared with the
// reference time history of the problem's output point, coordinate by coordinate, at the
// benchmark's output times; its error is the largest absolute difference. The library
// accepts 1e-1 ("low precision") and 1e-3 ("high precision"). docs/physics/benchmarks.md
// gives each problem's output point and times.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace heavesim::oracle {

/// max over samples and coordinates of |run - reference| (same units as the samples).
template <class Sample>
double iftomm_max_error(const std::vector<Sample>& run, const std::vector<Sample>& reference) {
  if (run.size() != reference.size()) throw std::invalid_argument("iftomm_max_error: sample counts differ");
  double error = 0.0;
  for (std::size_t k = 0; k < run.size(); ++k) error = std::max(error, (run[k] - reference[k]).cwiseAbs().maxCoeff());
  return error;
}

}  // namespace heavesim::oracle
