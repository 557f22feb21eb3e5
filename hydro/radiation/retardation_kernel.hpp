#pragma once
// Radiation memory (Cummins 1962; Ogilvie 1964), WAMIT mode order:
//   F_rad(t) = -A(inf) x''(t) - int_0^t K(t - tau) x'(tau) dtau,
//   K(t) = (2/pi) int_0^inf B(w) cos(w t) dw,
//   B(w) = int_0^inf K(t) cos(w t) dt,   A(w) = A(inf) - (1/w) int_0^inf K(t) sin(w t) dt.
// B(w) is taken piecewise linear through the BEM points, from B(0) = 0 at w = 0 to the
// last BEM frequency w_N, then tapered linearly to zero at (1 + taper) w_N: the cosine
// transform is then exact, segment by segment, with no quadrature. Cutting B off at w_N
// instead would leave a jump, a K(t) ~ B(w_N) sin(w_N t)/t tail that a truncated
// kernel cannot hold, and half of B(w_N) lost at w_N (Gibbs).
#include <vector>

#include "hydro/bem/bem_data.hpp"

namespace heavesim::hydro {

struct RetardationKernel {
  double time_step;             // dt [s]; K is sampled at t_k = k dt, k = 0 .. n-1
  std::vector<Matrix6> values;  // K(t_k) [N/m, N, N m per unit velocity and second]
  double duration() const { return time_step * (values.size() - 1); }
};

/// The longest kernel [s]: radiation memory of floating structures decays within a
/// few minutes (the cases' kernels are 60-120 s long); an hour holds any of them.
inline constexpr double max_kernel_duration = 3600.0;
/// The most samples a kernel may have: 1e5 Matrix6 are 29 MB, computed in about a
/// second from a few hundred BEM frequencies; the convolution memory reads all of
/// them at every evaluation (the default kernel has 1201).
inline constexpr int max_kernel_samples = 100000;

/// K(t) on [0, duration] [s] with step dt [s] from B(w) of `radiation`.
/// Throws ParameterError("kernel_duration") unless 0 < duration <= max_kernel_duration,
/// ParameterError("kernel_step") unless duration / max_kernel_samples <= time_step <=
/// duration / 10.
RetardationKernel retardation_kernel(const RadiationData& radiation, double duration, double time_step,
                                     double taper = 0.5);

/// B(w) and A(w) recovered from the sampled kernel (trapezoidal rule on [0, duration])
/// with A(inf) from the BEM data: the inverse transforms in the header comment.
struct FrequencyResponse {
  Matrix6 added_mass;  // A(w)
  Matrix6 damping;     // B(w)
};
FrequencyResponse kernel_frequency_response(const RetardationKernel& kernel, const Matrix6& added_mass_infinite,
                                            double angular_frequency);

/// B(w) linearly interpolated on the BEM grid as above (0 at w = 0, tapered beyond the last point).
Matrix6 interpolated_damping(const RadiationData& radiation, double angular_frequency, double taper = 0.5);

/// Memory force -int_0^t K(t - tau) v(tau) dtau [WAMIT order] at every sample of a
/// velocity history v_k = v(k dt) (same dt as the kernel), trapezoidal rule, for
/// checking other realisations of the memory (state space) against it.
std::vector<Eigen::Matrix<double, 6, 1>> convolve_velocity_history(
    const RetardationKernel& kernel, const std::vector<Eigen::Matrix<double, 6, 1>>& velocity);

}  // namespace heavesim::hydro
