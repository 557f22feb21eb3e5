#include "hydro/excitation/semisubmersible_heave.hpp"

#include <algorithm>
#include <cmath>

namespace heavesim::hydro {

double semisubmersible_heave_excitation(const SemisubmersibleHeaveEstimate& e, double w, double rho, double g) {
  const double k = w * w / g;  // deep-water wave number [1/m]
  const double froude_krylov = rho * g *
                               (e.pontoon_bottom_area * std::exp(-k * e.keel_depth) -
                                (e.pontoon_bottom_area - e.waterplane_area) * std::exp(-k * e.pontoon_top_depth));
  return froude_krylov - e.added_mass * w * w * std::exp(-k * e.added_mass_depth);
}

ExcitationData semisubmersible_heave_excitation_table(const SemisubmersibleHeaveEstimate& estimate,
                                                      std::vector<double> frequencies, double rho, double g) {
  std::sort(frequencies.begin(), frequencies.end());
  frequencies.erase(std::unique(frequencies.begin(), frequencies.end()), frequencies.end());
  ExcitationData table;
  table.angular_frequencies = frequencies;
  table.headings = {0.0};
  table.force.resize(1);
  for (double w : frequencies) {
    ComplexVector6 x = ComplexVector6::Zero();
    x[2] = semisubmersible_heave_excitation(estimate, w, rho, g);
    table.force[0].push_back(x);
  }
  return table;
}

}  // namespace heavesim::hydro
