#pragma once
// The frequency-domain RAO a case's BEM data give for its platform (the floating body its
// wave_excitation acts on), for `heavesim rao` to draw beside the time-domain points:
//   [-w^2 (M + A(w)) + i w (B(w) + B_ext) + C + C_ext] xi = X(w, beta)
// solved by hydro::frequency_domain_rao (hydro/analysis/frequency_domain_rao.hpp) on the
// BEM data interpolated to w: A, B linear in w between the BEM frequencies and held
// beyond them, X bilinear in w and beta (hydro/excitation/excitation_interpolation.hpp),
// which is what the run's elements do with the same files. From the case:
//   M      the platform body's rigid-body mass matrix about its frame origin (the BEM
//          reference point), WAMIT order [surge, sway, heave, roll, pitch, yaw];
//   C      its linear hydrostatics with gravity's part (WAMIT's "hydrostatic and
//          gravitational" matrix: the .hst as given with hst_includes_gravity, else
//          C + hydro::wamit_gravitational_stiffness);
//   B_ext  the sum of its linear_damping elements; C_ext the sum of its moorings.
// Quadratic damping, nonlinear hydrostatics and bodies attached to the platform are not
// in it (a linear single-body reference). Exists only when the platform has a radiation
// element, a wave_excitation from a BEM file (not the heave estimate) and linear
// hydrostatics; otherwise `reason` says what is missing.
#include <optional>
#include <string>

#include "app/case/case_definition.hpp"
#include "hydro/analysis/frequency_domain_rao.hpp"

namespace heavesim {

class FrequencyDomainReference {
 public:
  /// The reference of `definition`'s platform at the case's wave heading, or nothing
  /// (with `reason` set). Reads the case's BEM files (read_hydro_data).
  static std::optional<FrequencyDomainReference> of_case(const CaseDefinition& definition, std::string& reason);

  /// xi(w) [m/m for surge, sway, heave; rad/m for roll, pitch, yaw], motion = Re[xi a e^{i w t}].
  hydro::ComplexVector6 rao(double angular_frequency) const;
  /// The BEM frequencies [rad/s], ascending (where the reference is data, not held ends).
  const std::vector<double>& bem_frequencies() const { return bem_.radiation.angular_frequencies; }
  double heading() const { return heading_; }  // rad

 private:
  hydro::BemData bem_;             // radiation, excitation and C (with gravity) of the platform
  hydro::RaoSettings settings_;    // M, B_ext, C_ext
  double heading_ = 0.0;           // beta [rad]
};

/// The name of the case's first wave_excitation element and its body (the platform);
/// an InputError at `forces` when there is none (its wave_elevation channel is the RAO's input).
std::pair<std::string, std::string> wave_excitation_element(const CaseDefinition& definition);

}  // namespace heavesim
