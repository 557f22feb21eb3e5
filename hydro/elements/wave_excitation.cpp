#include "hydro/elements/wave_excitation.hpp"

#include <cmath>

#include "hydro/excitation/excitation_interpolation.hpp"

namespace heavesim::hydro {

WaveExcitation::WaveExcitation(std::string name, int link, const ExcitationData& excitation, WaveTrain waves,
                               Eigen::Vector2d mean_position)
    : name_(std::move(name)), link_(link), waves_(std::move(waves)), mean_position_(mean_position) {
  const auto& components = waves_.components();
  const Eigen::Index n = static_cast<Eigen::Index>(components.size());
  angular_frequencies_.resize(n);
  cosine_weights_.resize(7, n);
  sine_weights_.resize(7, n);
  cosines_.setZero(n);
  sines_.setZero(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const WaveComponent& c = components[j];
    const double phase = c.phase - c.wave_number * (mean_position.x() * std::cos(c.heading) +
                                                    mean_position.y() * std::sin(c.heading));
    const std::complex<double> wave = c.amplitude * std::polar(1.0, phase);  // a_j e^{i phi'_j}
    const ComplexVector6 amplitude = interpolate_excitation(excitation, c.angular_frequency, c.heading) * wave;
    angular_frequencies_[j] = c.angular_frequency;
    cosine_weights_.col(j) << amplitude.real(), wave.real();
    sine_weights_.col(j) << amplitude.imag(), wave.imag();
  }
  channels_ = {{"wave_elevation", "m", "incident wave elevation at the body's mean position (x0, y0)"},
               {"excitation_force_z", "N", "wave excitation force, world z"}};
}

const WaveExcitation::Vector7& WaveExcitation::evaluate(double t) const {
  if (t == cached_time_) return cached_value_;
  const double ramp = waves_.ramp()(t);
  if (ramp == 0.0) {
    cached_value_.setZero();
  } else {
    // Re[W e^{i w t}] = Re W cos w t - Im W sin w t.
    for (Eigen::Index j = 0; j < angular_frequencies_.size(); ++j) {
      const double phase = angular_frequencies_[j] * t;
      cosines_[j] = std::cos(phase);  // the compiler pairs these into one sincos call
      sines_[j] = std::sin(phase);
    }
    cached_value_.noalias() = cosine_weights_ * cosines_;
    cached_value_.noalias() -= sine_weights_ * sines_;
    cached_value_ *= ramp;
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
