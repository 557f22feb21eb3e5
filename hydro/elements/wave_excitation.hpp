#pragma once
// Linear wave excitation on one body (docs/physics/hydrodynamics.md §6; as WEC-Sim):
//   F(t) = R(t) sum_j Re[ X(w_j, beta_j) a_j e^{i (w_j t + phi_j - k_j (x0 cos beta_j + y0 sin beta_j))} ],
// WAMIT order [F; M about the body reference point], world axes; (x0, y0) is the
// body's mean horizontal position (linear theory: the wave is taken at the mean
// position, not the instantaneous one). X per component is interpolated once at
// construction (excitation_interpolation.hpp).
//
// Evaluation (the hot path of a sea-state run: 200 components at every right-hand side):
// with the phasors c_j + i s_j = e^{i w_j t},
//   [F; eta(x0, y0)] = R(t) W^T [c; s],  W = [Re[X_j a_j e^{i phi'_j}]; -Im[...]] (2N x 7),
// stored a row of eight per phasor (row-major 2N x 8, the last column zero): the seven
// sums gather a row a phasor (6 load components and the elevation at the mean position
// share the phasors; weighted_phasor_sums()). F depends on t only, so
//  * the last evaluation is kept and reused at the same t (a fixed-step Runge-Kutta
//    evaluates the midpoint twice and the end of a step again at the start of the next;
//    the recorder asks at the output time);
//  * the phasors come from a grid t_k = k D with D w_max <= 1/4: e^{i w t} =
//    e^{i w t_k} e^{i w (t - t_k)}. The grid phasors move from cell to cell by the kept
//    rotation e^{i w D} (a complex product per component) and are computed directly at the
//    first cell of every block of 32, so rounding grows over at most 31 products and the
//    phasors of a cell do not depend on the path that reached it. The rotation within the
//    cell, x = w (t - t_k) in [0, 1/4), is cos x and sin x as their Taylor polynomials to
//    x^8 and x^9 (errors below 3e-13 and 7e-15): a variable-step integrator then pays
//    about 25 flops per component instead of a sincos (~20 ns) at every new time (IDA
//    on the 3-hour sea: sincos was 12 % of the run). Phase errors stay below 1e-8 rad over
//    3 hours (tests/hydro/test_body_response.cpp).
// No allocation after construction. Not thread-safe (the cache is mutable state).
#include <limits>

#include "hydro/bem/bem_data.hpp"
#include "hydro/elements/body_motion.hpp"
#include "hydro/waves/wave_train.hpp"

namespace heavesim::hydro {

class WaveExcitation : public ForceElement {
 public:
  WaveExcitation(std::string name, int link, const ExcitationData& excitation, WaveTrain waves,
                 Eigen::Vector2d mean_position = Eigen::Vector2d::Zero());
  const std::string& name() const override { return name_; }
  void apply(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
             AppliedForces& forces) const override;
  /// Time, and the body's reference point (where the load acts).
  ElementDependencies dependencies() const override { return {true, true, false, false, false}; }
  const std::vector<ElementChannel>& channels() const override { return channels_; }
  void outputs(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
               std::span<double> values) const override;
  /// The excitation load at time t [WAMIT order, N and N m].
  Vector6 load(double t) const { return evaluate(t).head<6>(); }
  /// The incident wave elevation at the mean position (x0, y0) at time t [m], ramped.
  double elevation(double t) const { return evaluate(t)[6]; }

 private:
  using Vector7 = Eigen::Matrix<double, 7, 1>;
  /// [F (WAMIT order); eta(x0, y0)] at time t, ramped; cached for the last t.
  const Vector7& evaluate(double t) const;
  /// Sets the phasors to e^{i w_j t}.
  void update_phasors(double t) const;
  /// sums = W^T p over the phasors p (eight values, the last zero).
  void weighted_phasor_sums(double* sums) const;

  std::string name_;
  int link_;
  WaveTrain waves_;
  Eigen::Vector2d mean_position_;
  Eigen::VectorXd angular_frequencies_;                 // w_j [rad/s]
  /// W, a row per phasor: N/m, N m/m; column 6: m; column 7: zero (a row of eight
  /// doubles is two AVX2 vectors, weighted_phasor_sums()).
  Eigen::Matrix<double, Eigen::Dynamic, 8, Eigen::RowMajor> weights_;
  /// Moves the grid phasors to cell k.
  void move_grid(long k) const;
  double grid_step_ = 0.0;                              // D [s]
  Eigen::ArrayXd cell_cosines_, cell_sines_;            // e^{i w_j D}
  mutable Eigen::ArrayXd grid_cosines_, grid_sines_;    // e^{i w_j t_k}
  mutable long grid_cell_ = std::numeric_limits<long>::min();  // k (none yet)
  mutable Eigen::VectorXd phasors_;                     // [cos w_j t; sin w_j t]
  mutable double cached_time_ = std::numeric_limits<double>::quiet_NaN();
  mutable Vector7 cached_value_ = Vector7::Zero();
  std::vector<ElementChannel> channels_;
};

}  // namespace heavesim::hydro
