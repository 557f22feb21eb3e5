#pragma once
// Wave excitation transfer function X(w, beta) between the BEM points: linear in w and
// in beta (bilinear), on Re and Im separately (docs/physics/hydrodynamics.md §6; the
// alternative is polar; Cartesian keeps the phase continuous through zeros). Outside the
// BEM ranges the nearest end value is held (no extrapolation): below the lowest BEM
// frequency X keeps its long-wave value, above the highest it keeps the last one.
#include "hydro/bem/bem_data.hpp"

namespace heavesim::hydro {

ComplexVector6 interpolate_excitation(const ExcitationData& excitation, double angular_frequency, double heading);

}  // namespace heavesim::hydro
