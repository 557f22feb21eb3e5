#include "hydro/elements/wave_excitation.hpp"

#include <cmath>

#include "hydro/excitation/excitation_interpolation.hpp"

namespace heavesim::hydro {

WaveExcitation::WaveExcitation(std::string name, int link, const ExcitationData& excitation, WaveTrain waves,
                               Eigen::Vector2d mean_position)
    : name_(std::move(name)), link_(link), waves_(std::move(waves)), mean_position_(mean_position) {
  for (const WaveComponent& c : waves_.components()) {
    const double phase = c.phase - c.wave_number * (mean_position.x() * std::cos(c.heading) +
                                                    mean_position.y() * std::sin(c.heading));
    amplitude_.push_back(interpolate_excitation(excitation, c.angular_frequency, c.heading) * c.amplitude *
                         std::polar(1.0, phase));
  }
  channels_ = {{"wave_elevation", "m", "incident wave elevation at the body's mean position (x0, y0)"},
               {"excitation_force_z", "N", "wave excitation force, world z"}};
}

Vector6 WaveExcitation::load(double t) const {
  if (t == cached_time_) return cached_load_;
  const double ramp = waves_.ramp()(t);
  Vector6 f = Vector6::Zero();
  if (ramp != 0.0) {
    const auto& components = waves_.components();
    for (size_t j = 0; j < components.size(); ++j) {
      const std::complex<double> rotation = std::polar(1.0, components[j].angular_frequency * t);
      for (int i = 0; i < 6; ++i) f[i] += (amplitude_[j][i] * rotation).real();
    }
    f *= ramp;
  }
  cached_time_ = t;
  cached_load_ = f;
  return f;
}

void WaveExcitation::apply(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX>,
                           AppliedForces& forces) const {
  const Transform X = data.X_world_link[link_] * model.links[link_].X_link_body;
  add_load(forces, link_, X.translation(), load(t));
}

void WaveExcitation::outputs(double t, const Model&, const Data&, Eigen::Ref<const VectorX>,
                             std::span<double> values) const {
  values[0] = waves_.elevation(t, mean_position_.x(), mean_position_.y());
  values[1] = load(t)[2];
}

}  // namespace heavesim::hydro
