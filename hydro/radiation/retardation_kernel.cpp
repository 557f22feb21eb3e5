#include "hydro/radiation/retardation_kernel.hpp"

#include <cmath>

#include <fmt/format.h>

#include "kernel/parameter_error.hpp"

namespace heavesim::hydro {

Matrix6 interpolated_damping(const RadiationData& r, double w, double taper) {
  const auto& ws = r.angular_frequencies;
  if (w <= 0.0 || w >= (1.0 + taper) * ws.back()) return Matrix6::Zero();
  if (w > ws.back()) return r.damping.back() * (((1.0 + taper) * ws.back() - w) / (taper * ws.back()));
  if (w <= ws.front()) return r.damping.front() * (w / ws.front());
  const size_t n = std::upper_bound(ws.begin(), ws.end(), w) - ws.begin();  // ws[n-1] < w <= ws[n]
  if (n >= ws.size()) return r.damping.back();
  const double s = (w - ws[n - 1]) / (ws[n] - ws[n - 1]);
  return (1.0 - s) * r.damping[n - 1] + s * r.damping[n];
}

RetardationKernel retardation_kernel(const RadiationData& r, double duration, double dt, double taper) {
  if (!(duration > 0.0 && duration <= max_kernel_duration))
    throw ParameterError("kernel_duration", fmt::format("a kernel of {:g} s", duration),
                         fmt::format("0 < kernel_duration <= {:g} s", max_kernel_duration));
  // Ten samples at least: a coarser kernel resolves neither its decay nor its oscillation.
  if (!(dt > 0.0) || dt * 10 > duration)
    throw ParameterError("kernel_step", fmt::format("a step of {:g} s for a kernel of {:g} s", dt, duration),
                         "kernel_step <= kernel_duration / 10");
  if (duration / dt > max_kernel_samples - 1)
    throw ParameterError("kernel_step",
                         fmt::format("a step of {:g} s: {:.3g} samples for a kernel of {:g} s", dt, duration / dt + 1,
                                     duration),
                         fmt::format("at most {} samples: kernel_step >= kernel_duration / {} = {:.3g} s",
                                     max_kernel_samples, max_kernel_samples - 1, duration / (max_kernel_samples - 1)));
  // Knots of the piecewise-linear B: (0, 0) then the BEM points.
  std::vector<double> w{0.0};
  std::vector<Matrix6> b{Matrix6::Zero()};
  for (size_t n = 0; n < r.angular_frequencies.size(); ++n) {
    w.push_back(r.angular_frequencies[n]);
    b.push_back(r.damping[n]);
  }
  if (taper > 0.0) {
    w.push_back((1.0 + taper) * w.back());
    b.push_back(Matrix6::Zero());
  }
  RetardationKernel kernel{dt, {}};
  const int samples = static_cast<int>(std::floor(duration / dt + 0.5)) + 1;
  kernel.values.assign(samples, Matrix6::Zero());
  for (int k = 0; k < samples; ++k) {
    const double t = k * dt;
    Matrix6 sum = Matrix6::Zero();
    for (size_t s = 0; s + 1 < w.size(); ++s) {
      // int_{w0}^{w1} (b0 + m (w - w0)) cos(w t) dw, m = (b1 - b0)/(w1 - w0), by parts:
      //   [(b(w) sin(w t))/t + m cos(w t)/t^2]_{w0}^{w1};  at t = 0: (b0 + b1)(w1 - w0)/2.
      const double w0 = w[s], w1 = w[s + 1];
      if (t == 0.0) {
        sum += 0.5 * (b[s] + b[s + 1]) * (w1 - w0);
      } else {
        const Matrix6 slope = (b[s + 1] - b[s]) / (w1 - w0);
        sum += (b[s + 1] * std::sin(w1 * t) - b[s] * std::sin(w0 * t)) / t +
               slope * ((std::cos(w1 * t) - std::cos(w0 * t)) / (t * t));
      }
    }
    kernel.values[k] = (2.0 / M_PI) * sum;
  }
  return kernel;
}

FrequencyResponse kernel_frequency_response(const RetardationKernel& kernel, const Matrix6& added_mass_infinite,
                                            double w) {
  Matrix6 cosine = Matrix6::Zero(), sine = Matrix6::Zero();
  const size_t n = kernel.values.size();
  for (size_t k = 0; k < n; ++k) {
    const double t = k * kernel.time_step, weight = (k == 0 || k + 1 == n) ? 0.5 : 1.0;
    cosine += weight * std::cos(w * t) * kernel.values[k];
    sine += weight * std::sin(w * t) * kernel.values[k];
  }
  return {added_mass_infinite - sine * kernel.time_step / w, cosine * kernel.time_step};
}

std::vector<Eigen::Matrix<double, 6, 1>> convolve_velocity_history(
    const RetardationKernel& kernel, const std::vector<Eigen::Matrix<double, 6, 1>>& velocity) {
  const size_t n = velocity.size(), m = kernel.values.size();
  std::vector<Eigen::Matrix<double, 6, 1>> force(n, Eigen::Matrix<double, 6, 1>::Zero());
  for (size_t k = 1; k < n; ++k) {
    // int_0^{t_k} K(t_k - tau) v(tau) dtau, trapezoidal, truncated at the kernel's length.
    const size_t first = k + 1 > m ? k + 1 - m : 0;
    Eigen::Matrix<double, 6, 1> sum = Eigen::Matrix<double, 6, 1>::Zero();
    for (size_t j = first; j <= k; ++j) {
      const double weight = (j == first || j == k) ? 0.5 : 1.0;
      sum += weight * (kernel.values[k - j] * velocity[j]);
    }
    force[k] = -kernel.time_step * sum;
  }
  return force;
}

}  // namespace heavesim::hydro
