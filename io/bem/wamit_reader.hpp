#pragma once
// Readers of WAMIT's numeric output files (WAMIT User Manual v7, ch. 4), which are
// nondimensional; dimensionalised with rho, g and ULEN = L (docs/physics/hydrodynamics.md §10):
//   A = rho L^k A_bar,  B = rho w L^k B_bar,  k = 3, 4, 5 (translation-translation,
//   mixed, rotation-rotation);  C = rho g L^k' C_bar, k' = 2, 3, 4;
//   X = rho g L^m X_bar, m = 2 (forces), 3 (moments).
//  .1    PER I J A_bar B_bar      PER = -1: w = 0 and PER = 0: w = inf (no B_bar column)
//  .3    PER BETA I |X| phase(deg) Re Im
//  .hst  I J C_bar
// Missing (I, J) pairs are zero (WAMIT omits them). Everything is checked and a
// DataError names the file, the line, what was found and what was expected.
#include "hydro/bem/bem_data.hpp"
#include "hydro/data_error.hpp"

namespace heavesim::bem {

struct WamitScaling {
  double density = 1025.0;     // rho [kg/m^3]
  double gravity = 9.81;       // g [m/s^2]
  double length_scale = 1.0;   // ULEN [m]
};

hydro::RadiationData read_wamit_1(const std::string& path, const WamitScaling& scaling = {});
hydro::ExcitationData read_wamit_3(const std::string& path, const WamitScaling& scaling = {});
hydro::Matrix6 read_wamit_hst(const std::string& path, const WamitScaling& scaling = {});

/// basename.1, basename.3 and basename.hst, with their frequencies checked to agree.
hydro::BemData read_wamit(const std::string& basename, const WamitScaling& scaling = {});

/// Relative tolerance of the symmetry check on A (B is symmetrised unchecked): |X_ij - X_ji| <= tol sqrt(|X_ii X_jj|)
/// (BEM solutions are symmetric only to discretisation error; the MSS file has 5e-4).
inline constexpr double bem_symmetry_tolerance = 0.02;

/// (M + M^T) / 2, summed as halves: M_ij + M_ji overflows for entries near the largest
/// double, their halves do not.
inline hydro::Matrix6 symmetric_part(const hydro::Matrix6& M) { return 0.5 * M + 0.5 * M.transpose(); }

}  // namespace heavesim::bem
