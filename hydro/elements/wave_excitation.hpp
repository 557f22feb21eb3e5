#pragma once
// Linear wave excitation on one body (hydro-reference.md sec. 1.1, WEC-Sim):
//   F(t) = R(t) sum_j Re[ X(w_j, beta_j) a_j e^{i (w_j t + phi_j - k_j (x0 cos beta_j + y0 sin beta_j))} ],
// WAMIT order [F; M about the body reference point], world axes; (x0, y0) is the
// body's mean horizontal position (linear theory: the wave is taken at the mean
// position, not the instantaneous one). X per component is interpolated once at
// construction (excitation_interpolation.hpp), so apply() only sums cosines.
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
  const std::vector<ElementChannel>& channels() const override { return channels_; }
  void outputs(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
               std::span<double> values) const override;
  /// The excitation load at time t [WAMIT order, N and N m].
  Vector6 load(double t) const;

 private:
  std::string name_;
  int link_;
  WaveTrain waves_;
  Eigen::Vector2d mean_position_;
  std::vector<ComplexVector6> amplitude_;  // X(w_j, beta_j) a_j e^{i(phi_j - k_j x0 . e_beta)}
  std::vector<ElementChannel> channels_;
  // The load depends on t only, and an implicit integrator evaluates the forces many
  // times at one t (Newton iterations, the Newton matrix's difference columns): the last
  // sum is kept. Not thread-safe; an element belongs to one system.
  mutable double cached_time_ = std::numeric_limits<double>::quiet_NaN();
  mutable Vector6 cached_load_ = Vector6::Zero();
};

}  // namespace heavesim::hydro
