#include "hydro/elements/wave_excitation.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "hydro/excitation/excitation_interpolation.hpp"
#include "kernel/math/cpu_dispatch.hpp"
#include "kernel/math/vector_libm.hpp"

namespace heavesim::hydro {

WaveExcitation::WaveExcitation(std::string name, int link, const ExcitationData& excitation, WaveTrain waves,
                               Eigen::Vector2d mean_position)
    : name_(std::move(name)), link_(link), waves_(std::move(waves)), mean_position_(mean_position) {
  const auto& components = waves_.components();
  const Eigen::Index n = static_cast<Eigen::Index>(components.size());
  angular_frequencies_.resize(n);
  weights_.setZero(2 * n, 8);
  phasors_.setZero(2 * n);
  for (Eigen::ArrayXd* a : {&grid_cosines_, &grid_sines_}) a->setZero(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const WaveComponent& c = components[j];
    const double phase = c.phase - c.wave_number * (mean_position.x() * std::cos(c.heading) +
                                                    mean_position.y() * std::sin(c.heading));
    const std::complex<double> wave = c.amplitude * std::polar(1.0, phase);  // a_j e^{i phi'_j}
    const ComplexVector6 amplitude = interpolate_excitation(excitation, c.angular_frequency, c.heading) * wave;
    angular_frequencies_[j] = c.angular_frequency;
    // Re[W e^{i w t}] = Re W cos w t - Im W sin w t
    weights_.row(j).head<7>() << amplitude.real().transpose(), wave.real();
    weights_.row(n + j).head<7>() << -amplitude.imag().transpose(), -wave.imag();
  }
  // The grid: D w_max <= 1/4.
  const double highest = n > 0 ? angular_frequencies_.cwiseAbs().maxCoeff() : 0.0;
  grid_step_ = highest > 0.0 ? 0.25 / highest : 1.0;
  cell_cosines_ = (angular_frequencies_.array() * grid_step_).cos();
  cell_sines_ = (angular_frequencies_.array() * grid_step_).sin();
  channels_ = {{"wave_elevation", "m", "incident wave elevation at the body's mean position (x0, y0)"},
               {"excitation_force_z", "N", "wave excitation force, world z"}};
}

HEAVESIM_CLONED_FOR_AVX2 void WaveExcitation::move_grid(long k) const {
  // Cell k's phasors are always the same product: the block's first cell a = 32 floor(k / 32)
  // from t_a directly, then k - a rotations by e^{i w D} in turn. A step to the next cell is
  // one more rotation; any other move (back, a jump, a new block) starts again from the
  // block's first cell. So the phasors -- and every load -- at a time do not depend on the
  // times asked before (bit for bit: tests/hydro/test_body_response.cpp), and rounding
  // grows over at most 31 products.
  constexpr long block = 32;
  const long first = k >= 0 ? k / block * block : -((-k + block - 1) / block) * block;
  long from = grid_cell_;
  if (!(grid_cell_ != std::numeric_limits<long>::min() && k >= grid_cell_ && grid_cell_ >= first)) {
    const double t_a = static_cast<double>(first) * grid_step_;
    // Every restart pays a cos and a sin per component (IDA's steps move back often):
    // two components at a time through libmvec, 4 ulp (kernel/math/vector_libm.hpp).
    vector_libm::cos_sin_of_scaled(angular_frequencies_.data(), t_a, grid_cosines_.data(), grid_sines_.data(),
                                   angular_frequencies_.size());
    from = first;
  }
  // One rotation a pass, a plain loop the compiler vectorizes (4 doubles a vector in the
  // x86-64-v3 clone); Eigen's three array statements a rotation were 3.5 % of the H1 run.
  const Eigen::Index n = angular_frequencies_.size();
  double* __restrict cosines = grid_cosines_.data();
  double* __restrict sines = grid_sines_.data();
  const double* cell_c = cell_cosines_.data();
  const double* cell_s = cell_sines_.data();
  for (; from < k; ++from)
    for (Eigen::Index j = 0; j < n; ++j) {  // (c + i s)(rc + i rs)
      const double cosine = cosines[j] * cell_c[j] - sines[j] * cell_s[j];
      sines[j] = cosines[j] * cell_s[j] + sines[j] * cell_c[j];
      cosines[j] = cosine;
    }
  grid_cell_ = k;
}

// The within-cell rotation is a plain loop the compiler vectorizes; 3.6 % of the 3-hour H1
// run went with its AVX2 version (docs/performance.md, 2026-11-29).
HEAVESIM_CLONED_FOR_AVX2 void WaveExcitation::update_phasors(double t) const {
  const long k = static_cast<long>(std::floor(t / grid_step_));
  if (k != grid_cell_) move_grid(k);
  // e^{i x} for x = w (t - t_k) in [0, 1/4), by Horner on x^2: cos to x^8, sin to x^9;
  // one fused pass the compiler vectorizes (Eigen's statement-by-statement form made seven).
  const double offset = t - static_cast<double>(k) * grid_step_;
  const Eigen::Index n = angular_frequencies_.size();
  const double* w = angular_frequencies_.data();
  const double* grid_c = grid_cosines_.data();
  const double* grid_s = grid_sines_.data();
  double* c_out = phasors_.data();
  double* s_out = phasors_.data() + n;
  for (Eigen::Index j = 0; j < n; ++j) {
    const double x = w[j] * offset, x2 = x * x;
    const double cell_c = 1.0 - x2 * (1.0 / 2.0) * (1.0 - x2 * (1.0 / 12.0) * (1.0 - x2 * (1.0 / 30.0) * (1.0 - x2 * (1.0 / 56.0))));
    const double cell_s =
        x * (1.0 - x2 * (1.0 / 6.0) * (1.0 - x2 * (1.0 / 20.0) * (1.0 - x2 * (1.0 / 42.0) * (1.0 - x2 * (1.0 / 72.0)))));
    c_out[j] = grid_c[j] * cell_c - grid_s[j] * cell_s;
    s_out[j] = grid_s[j] * cell_c + grid_c[j] * cell_s;
  }
}

// The sums a phasor at a time: the eight running sums are two vectors of four doubles (GCC's
// and Clang's vector extensions: one AVX2 register each, a fused multiply-add each a phasor
// in the x86-64-v3 clone, two SSE2 registers each elsewhere), each sum adding its terms in
// phasor order. Left to itself the compiler vectorized across phasors with transposes;
// Eigen's product of the transposed (2N x 7) weights ran on two doubles a vector: 10 % of
// the 3-hour H1 run's instructions (docs/performance.md, "Issue #18, thirteenth round").
HEAVESIM_CLONED_FOR_AVX2 void WaveExcitation::weighted_phasor_sums(double* sums) const {
  using FourDoubles = double __attribute__((vector_size(4 * sizeof(double))));
  FourDoubles first = {0.0, 0.0, 0.0, 0.0}, second = {0.0, 0.0, 0.0, 0.0};
  const double* row = weights_.data();
  const double* phasor = phasors_.data();
  const Eigen::Index count = phasors_.size();
  for (Eigen::Index j = 0; j < count; ++j, row += 8) {
    FourDoubles low, high;
    std::memcpy(&low, row, sizeof low);  // unaligned loads
    std::memcpy(&high, row + 4, sizeof high);
    first += low * phasor[j];
    second += high * phasor[j];
  }
  std::memcpy(sums, &first, sizeof first);
  std::memcpy(sums + 4, &second, sizeof second);
}

const WaveExcitation::Vector7& WaveExcitation::evaluate(double t) const {
  if (t == cached_time_) return cached_value_;
  const double ramp = waves_.ramp()(t);
  if (ramp == 0.0) {
    cached_value_.setZero();
  } else {
    update_phasors(t);
    double sums[8];
    weighted_phasor_sums(sums);
    cached_value_ = ramp * Eigen::Map<const Vector7>(sums);
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
