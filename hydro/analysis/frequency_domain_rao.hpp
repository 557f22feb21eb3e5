#pragma once
// First-order motion RAOs of one rigid body in the frequency domain (the naval
// architect's check of BEM data; docs/physics/hydrodynamics.md §11), WAMIT order and
// conventions, motion = Re[xi a e^{i w t}] per unit wave amplitude a:
//   [-w^2 (M + A(w)) + i w (B(w) + B_ext) + C + C_ext] xi = X(w, beta).
// M is the body's 6x6 mass matrix about the BEM reference point (WAMIT order, e.g. from
// a .frc file), C the restoring matrix including gravity (as a WAMIT .hst with a CG
// given). Solved with Eigen's partial-pivoting LU at each BEM frequency.
#include "hydro/bem/bem_data.hpp"

namespace heavesim::hydro {

struct RaoSettings {
  Matrix6 mass = Matrix6::Zero();                  // M [kg, kg m, kg m^2]
  Matrix6 external_damping = Matrix6::Zero();      // B_ext [N s/m, ...]
  Matrix6 external_stiffness = Matrix6::Zero();    // C_ext [N/m, ...] (moorings)
};

/// xi at BEM frequency index n and heading index h [m/m, rad/m].
ComplexVector6 frequency_domain_rao(const BemData& bem, const RaoSettings& settings, size_t frequency_index,
                                    size_t heading_index);

}  // namespace heavesim::hydro
