#pragma once
// Dimensional first-order BEM coefficients of one body, in WAMIT's conventions
// (docs/physics/hydrodynamics.md §1): modes [surge, sway, heave, roll, pitch, yaw] about the
// BEM reference point (the body frame origin of the BEM run), world axes with z up;
// harmonic quantities as Re[X e^{+i w t}]; heading beta = direction the waves travel,
// from +x toward +y; excitation per unit incident-wave amplitude, the wave
// eta = Re[a e^{i w t}] measured at the reference point's (x, y).
// Units: A in kg, kg m, kg m^2 (translation-translation, mixed, rotation-rotation);
// B in N s/m, N s, N m s; C in N/m, N, N m; X in N/m (forces), N m/m (moments).
#include <complex>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace heavesim::hydro {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using ComplexVector6 = Eigen::Matrix<std::complex<double>, 6, 1>;

struct RadiationData {
  std::vector<double> angular_frequencies;  // w_i [rad/s], ascending, 0 < w < inf
  std::vector<Matrix6> added_mass;          // A(w_i)
  std::vector<Matrix6> damping;             // B(w_i)
  Matrix6 added_mass_zero = Matrix6::Zero();      // A(0), when the file has the PER = -1 rows
  bool has_added_mass_zero = false;
  Matrix6 added_mass_infinite = Matrix6::Zero();  // A(inf), from the PER = 0 rows (required)
};

struct ExcitationData {
  std::vector<double> angular_frequencies;  // w_i [rad/s], ascending
  std::vector<double> headings;             // beta_h [rad], ascending
  std::vector<std::vector<ComplexVector6>> force;  // force[h][i] = X(w_i, beta_h)
};

struct BemData {
  RadiationData radiation;
  ExcitationData excitation;
  Matrix6 hydrostatic_stiffness = Matrix6::Zero();  // C as the .hst gives it
};

}  // namespace heavesim::hydro
