#pragma once
// Reader of WEC-Sim's BEMIO HDF5 files (writeBEMIOH5.m; docs/physics/hydrodynamics.md §10)
// into hydro's BEM types: dimensional SI, WAMIT conventions (modes [surge, sway, heave,
// roll, pitch, yaw] about the BEM reference point, world axes z up, e^{+i w t}, heading
// = direction of travel from +x toward +y), as the WAMIT readers give them.
//
// The file's first body (/body1) is read, and of its (6, 6 Nb) coupling blocks its own
// (columns 1-6). BEMIO stores the coefficients in WAMIT's phase convention, and with
// /simulation_parameters/scaled = 0 nondimensional:
//   A_bar = A / rho, B_bar = B / (rho w), X_bar = X / (rho g), K_bar = C / (rho g),
// dimensionalised here with the case's rho and g (as WEC-Sim does with simu.rho, g).
// With scaled = 1 they are dimensional for the file's /simulation_parameters/rho and g
// and are rescaled to the case's (A, B by rho_case / rho_file; X, C by
// rho_case g_case / (rho_file g_file)).
// Array shapes are read from the file: (6, 6 Nb, Nf) and (6, Nh, Nf) as hydrodynamics.md §10 lists
// them (C order), or the reverse (MATLAB's column-major order written unpermuted);
// square 6 x 6 matrices cannot tell the two apart and are taken as [row][column].
// Frequencies from /simulation_parameters/w [rad/s]; a w = 0 entry is A(0) and is not
// used for B or X. A(inf) is .../added_mass/inf_freq (required). Headings
// /simulation_parameters/wave_dir [deg].
// Hydrostatic stiffness: linear_restoring_stiffness, buoyancy and waterplane only, like
// a WAMIT .hst (the multibody kernel applies the body's weight at its centre of mass;
// a matrix with gravity terms would count them twice).
// Errors are hydro::DataError naming "<file>:<dataset>", what was found and expected.
#include <string>

#include "io/bem/bem_arrays.hpp"

namespace heavesim::bem {

hydro::RadiationData read_bemio_radiation(const std::string& path, const CaseFluid& fluid);
hydro::ExcitationData read_bemio_excitation(const std::string& path, const CaseFluid& fluid);
hydro::Matrix6 read_bemio_hydrostatic_stiffness(const std::string& path, const CaseFluid& fluid);

}  // namespace heavesim::bem
