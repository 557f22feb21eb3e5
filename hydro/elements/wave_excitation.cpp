#include "hydro/elements/wave_excitation.hpp"

#include <algorithm>
#include <cmath>

#include "hydro/excitation/excitation_interpolation.hpp"

namespace heavesim::hydro {

WaveExcitation::WaveExcitation(std::string name, int link, const ExcitationData& excitation, WaveTrain waves,
                               Eigen::Vector2d mean_position)
    : name_(std::move(name)), link_(link), waves_(std::move(waves)), mean_position_(mean_position) {
  const auto& components = waves_.components();
  const Eigen::Index n = static_cast<Eigen::Index>(components.size());
  angular_frequencies_.resize(n);
  weights_.resize(2 * n, 7);
  phasors_.setZero(2 * n);
  rotation_cosines_.setZero(n);
  rotation_sines_.setZero(n);
  scratch_.setZero(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const WaveComponent& c = components[j];
    const double phase = c.phase - c.wave_number * (mean_position.x() * std::cos(c.heading) +
                                                    mean_position.y() * std::sin(c.heading));
    const std::complex<double> wave = c.amplitude * std::polar(1.0, phase);  // a_j e^{i phi'_j}
    const ComplexVector6 amplitude = interpolate_excitation(excitation, c.angular_frequency, c.heading) * wave;
    angular_frequencies_[j] = c.angular_frequency;
    weights_.row(j) << amplitude.real().transpose(), wave.real();  // Re[W e^{i w t}] = Re W cos w t - Im W sin w t
    weights_.row(n + j) << -amplitude.imag().transpose(), -wave.imag();
  }
  channels_ = {{"wave_elevation", "m", "incident wave elevation at the body's mean position (x0, y0)"},
               {"excitation_force_z", "N", "wave excitation force, world z"}};
}

void WaveExcitation::update_phasors(double t) const {
  const double delta = t - phasor_time_;  // NaN before the first evaluation
  // Within a few roundings of tau: the same instant (an output time set to the requested
  // value rather than the accumulated one, e.g.).
  const double tolerance = 64.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(t));
  if (std::abs(delta) <= tolerance) return;
  if (rotations_since_direct_ < 1024 && std::abs(delta - rotation_step_) <= tolerance) {
    // (c + i s)(rc + i rs). The phasors now stand for tau + delta_kept, which differs from
    // t by the rounding of the integrator's own time sums (a few ulp of t per step; at
    // most 1024 of them before the next direct evaluation: ~1e-9 s at t = 3 h, a phase
    // error of ~3e-9 rad at 3 rad/s). tau is set to t, so that the next increment is
    // compared as the integrator made it.
    const Eigen::Index n = angular_frequencies_.size();
    auto cosines = phasors_.head(n).array();
    auto sines = phasors_.tail(n).array();
    scratch_ = phasors_.head(n);
    cosines = scratch_.array() * rotation_cosines_.array() - sines * rotation_sines_.array();
    sines = scratch_.array() * rotation_sines_.array() + sines * rotation_cosines_.array();
    phasor_time_ = t;
    ++rotations_since_direct_;
    return;
  }
  // Directly from t; a step seen twice in a row (a fixed-step method: h/2 for RK4) is
  // kept as the rotation for the next evaluations. Adaptive steps keep changing and are
  // never kept, so they cost one sincos per component, as a direct sum does.
  const bool keep_step = std::abs(delta - previous_step_) <= tolerance && !(std::abs(delta - rotation_step_) <= tolerance);
  const Eigen::Index n = angular_frequencies_.size();
  for (Eigen::Index j = 0; j < n; ++j) {
    const double w = angular_frequencies_[j];
    phasors_[j] = std::cos(w * t);  // the compiler pairs each cos with its sin in one sincos call
    phasors_[n + j] = std::sin(w * t);
    if (keep_step) {
      rotation_cosines_[j] = std::cos(w * delta);
      rotation_sines_[j] = std::sin(w * delta);
    }
  }
  if (keep_step) rotation_step_ = delta;
  previous_step_ = delta;
  phasor_time_ = t;
  rotations_since_direct_ = 0;
}

const WaveExcitation::Vector7& WaveExcitation::evaluate(double t) const {
  if (t == cached_time_) return cached_value_;
  const double ramp = waves_.ramp()(t);
  if (ramp == 0.0) {
    cached_value_.setZero();
  } else {
    update_phasors(t);
    cached_value_.noalias() = ramp * (weights_.transpose() * phasors_);
  }
  cached_time_ = t;
  return cached_value_;
}

void WaveExcitation::apply(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX>,
                           AppliedForces& forces) const {
  const Transform X = data.X_world_link[link_] * model.links[link_].X_link_body;
  add_load(forces, link_, X.translation(), load(t));
}

void WaveExcitation::outputs(double t, const Model&, const Data&, Eigen::Ref<const VectorX>,
                             std::span<double> values) const {
  const Vector7& value = evaluate(t);
  values[0] = value[6];
  values[1] = value[2];
}

}  // namespace heavesim::hydro
