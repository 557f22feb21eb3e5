#pragma once
// Hand-estimate heave excitation of a twin-pontoon semi-submersible when no BEM data
// are at hand (docs/physics/drilling-rig.md §4, "Fallback hydrodynamics"), deep water
// (k = w^2 / g):
//   X3(w) = rho g [A_pb e^{-k d_keel} - (A_pb - A_wp) e^{-k d_top}] - A33 w^2 e^{-k d_a}
// the Froude-Krylov pressure of the incident wave on the horizontal pontoon faces
// (bottoms at the keel depth pushing up, the tops outside the columns pushing down)
// plus the pontoons' added mass times the vertical fluid acceleration at their mid
// depth d_a (the diffraction term). X3 [N/m] is real: in phase with the elevation at
// the reference point for X3 > 0 (long waves: X3 -> rho g A_wp), in antiphase beyond
// the cancellation frequency. The estimate ignores the wave's phase differences over
// the hull, so it is the same for every heading; surge, sway and the moments are 0.
#include <vector>

#include "hydro/bem/bem_data.hpp"

namespace heavesim::hydro {

struct SemisubmersibleHeaveEstimate {
  double pontoon_bottom_area = 0.0;  // A_pb [m^2], both pontoons' bottoms
  double waterplane_area = 0.0;      // A_wp [m^2], the columns' cross sections
  double keel_depth = 0.0;           // d_keel [m], pontoon bottoms below the still-water level
  double pontoon_top_depth = 0.0;    // d_top [m], pontoon tops
  double added_mass = 0.0;           // A33 [kg]
  double added_mass_depth = 0.0;     // d_a [m], where the diffraction term takes the fluid acceleration
};

/// X3(w) [N/m] of the estimate, for water density rho [kg/m^3] and gravity g [m/s^2].
double semisubmersible_heave_excitation(const SemisubmersibleHeaveEstimate& estimate, double angular_frequency,
                                        double rho, double g);

/// The estimate as excitation data (heave only, one heading) at the given angular
/// frequencies [rad/s], which are sorted and made unique: built at the wave components'
/// own frequencies, WaveExcitation's interpolation returns X3 exactly.
ExcitationData semisubmersible_heave_excitation_table(const SemisubmersibleHeaveEstimate& estimate,
                                                      std::vector<double> angular_frequencies, double rho, double g);

}  // namespace heavesim::hydro
