#include "hydro/excitation/excitation_interpolation.hpp"

#include <algorithm>

namespace heavesim::hydro {
namespace {

/// Index n and weight s with value ~ (1 - s) x[n] + s x[n + 1]; held at the ends.
std::pair<size_t, double> bracket(const std::vector<double>& x, double value) {
  if (x.size() == 1 || value <= x.front()) return {0, 0.0};
  if (value >= x.back()) return {x.size() - 2, 1.0};
  const size_t n = std::upper_bound(x.begin(), x.end(), value) - x.begin() - 1;
  return {n, (value - x[n]) / (x[n + 1] - x[n])};
}

}  // namespace

ComplexVector6 interpolate_excitation(const ExcitationData& x, double w, double beta) {
  const auto [n, s] = bracket(x.angular_frequencies, w);
  const auto [h, r] = bracket(x.headings, beta);
  const size_t n1 = std::min(n + 1, x.angular_frequencies.size() - 1), h1 = std::min(h + 1, x.headings.size() - 1);
  const ComplexVector6 at_h0 = (1.0 - s) * x.force[h][n] + s * x.force[h][n1];
  const ComplexVector6 at_h1 = (1.0 - s) * x.force[h1][n] + s * x.force[h1][n1];
  return (1.0 - r) * at_h0 + r * at_h1;
}

}  // namespace heavesim::hydro
