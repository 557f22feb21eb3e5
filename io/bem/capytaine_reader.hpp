#pragma once
// Reader of Capytaine's NetCDF4 datasets (cpt.assemble_dataset, saved with
// separate_complex_values; docs/physics/hydrodynamics.md §10) into hydro's BEM types:
// dimensional SI, WAMIT conventions (modes [surge, sway, heave, roll, pitch, yaw] about
// the BEM reference point, world axes z up, e^{+i w t}, heading = direction of travel
// from +x toward +y), as the WAMIT readers give them.
//
// NetCDF4 is HDF5 with every dimension a dimension scale: the axes of each variable
// are looked up by their dimension names, in whatever order they are stored.
//   added_mass, radiation_damping  (omega, radiating_dof, influenced_dof):
//       A_ij = added_mass[influenced_dof = i, radiating_dof = j] (force i, motion j)
//   diffraction_force + Froude_Krylov_force  (omega, wave_direction, influenced_dof,
//       complex = ["re", "im"]): the excitation X, per unit wave amplitude
//   hydrostatic_stiffness  (influenced_dof, radiating_dof)
//   rho, g: the fluid the dimensional coefficients were computed for; they are
//       rescaled to the case's (A, B by rho_case / rho; X, C by rho_case g_case / (rho g)).
// Dofs are the rigid-body names Surge, Sway, Heave, Roll, Pitch, Yaw (modes 1-6); a
// mode the file lacks is zero (as WAMIT omits entries). omega [rad/s]: an omega = 0
// entry is A(0); the omega = inf entry is A(inf) (required); their damping and
// excitation (zero or NaN in Capytaine) are not used. wave_direction [rad].
// Capytaine writes harmonic quantities as Re[X e^{-i w t}]: X is conjugated
// (imaginary part negated) to WAMIT's Re[X e^{+i w t}], as WEC-Sim's readCAPYTAINE does.
// Hydrostatic stiffness: taken as buoyancy and waterplane only, like a WAMIT .hst (the
// multibody kernel applies the body's weight at its centre of mass). Capytaine's rigid-
// body stiffness can include the -m g z_G terms of roll and pitch when the body has a
// centre of mass; such a matrix counts gravity twice in roll and pitch (heave is
// unaffected).
// Errors are hydro::DataError naming "<file>:/<variable>", what was found and expected.
#include <string>

#include "io/bem/bem_arrays.hpp"

namespace heavesim::bem {

hydro::RadiationData read_capytaine_radiation(const std::string& path, const CaseFluid& fluid);
hydro::ExcitationData read_capytaine_excitation(const std::string& path, const CaseFluid& fluid);
hydro::Matrix6 read_capytaine_hydrostatic_stiffness(const std::string& path, const CaseFluid& fluid);

}  // namespace heavesim::bem
