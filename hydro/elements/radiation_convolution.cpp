#include "hydro/elements/radiation_convolution.hpp"

#include <cmath>

namespace heavesim::hydro {

RadiationConvolution::RadiationConvolution(std::string name, int link, RetardationKernel kernel)
    : name_(std::move(name)), link_(link), kernel_(std::move(kernel)),
      history_(kernel_.values.size() + 1, Vector6::Zero()) {}

void RadiationConvolution::apply(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX>,
                                 AppliedForces& forces) const {
  const BodyMotion m = body_motion(model, data, link_);
  const double dt = kernel_.time_step;
  const long size = static_cast<long>(history_.size());
  const long current = static_cast<long>(std::floor(t / dt + 1e-9));  // t_n <= t
  if (current <= 0 && newest_sample_ > 1) {  // a new run from t = 0 with this element: forget the old one
    for (Vector6& sample : history_) sample.setZero();
    newest_sample_ = -1;
  }
  // Store the samples this evaluation is the first to reach (a jump of several steps
  // repeats the current velocity; the run starts from rest: older samples are zero).
  for (long n = std::max(newest_sample_ + 1, current - size + 1); n <= current; ++n) history_[n % size] = m.velocity;
  newest_sample_ = std::max(newest_sample_, current);
  // An evaluation exactly at a sample time overwrites it: with a fixed-step explicit
  // method the last such evaluation is the first stage of the next step, i.e. the
  // accepted state, not the previous step's trial stage at the same time.
  const double fraction_raw = t / dt - static_cast<double>(current);
  if (fraction_raw < 1e-9 && current == newest_sample_) history_[current % size] = m.velocity;
  // F = -int_0^{T_K} K(s) v(t - s) ds: the partial interval [t_n, t] with the current
  // velocity, then the stored samples v(t_n - k dt) against K(t - t_n + k dt),
  // K linearly interpolated between its samples.
  const double fraction = std::max(0.0, fraction_raw);  // (t - t_n)/dt in [0, 1)
  const int samples = static_cast<int>(kernel_.values.size());
  auto kernel_at = [&](double s_over_dt) -> Matrix6 {
    const int k = static_cast<int>(s_over_dt);
    if (k + 1 >= samples) return Matrix6::Zero();
    const double r = s_over_dt - k;
    return (1.0 - r) * kernel_.values[k] + r * kernel_.values[k + 1];
  };
  Vector6 integral = 0.5 * fraction * dt * (kernel_.values[0] * m.velocity + kernel_at(fraction) * history_[current % size]);
  for (long k = 0; k + 1 < size && current - k - 1 >= 0; ++k) {
    const double s0 = fraction + k, s1 = fraction + k + 1;
    if (s1 + 1 >= samples) break;
    integral += 0.5 * dt * (kernel_at(s0) * history_[(current - k) % size] + kernel_at(s1) * history_[(current - k - 1) % size]);
  }
  add_load(forces, link_, m.X_world_body.translation(), -integral);
}

}  // namespace heavesim::hydro
