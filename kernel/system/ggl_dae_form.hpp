#pragma once
// A MultibodySystem as a DaeSystem for IDA: the stabilized index-2 form of Gear, Gupta
// & Leimkuhler (1985), y_dae = [q; v; z; lambda (m); mu (m)] (ggl_dae_form.cpp).
#include <vector>

#include "kernel/system/dae_system.hpp"
#include "kernel/system/dynamics_differentiator.hpp"
#include "kernel/system/fastest_mode.hpp"
#include "kernel/system/joint_stop_events.hpp"
#include "kernel/system/multibody_system.hpp"

namespace heavesim {

class GglDaeForm final : public DaeSystem {
 public:
  explicit GglDaeForm(MultibodySystem& system);

  int dae_size() const override { return system_.size() + 2 * kept_rows(); }
  void differential_mask(VectorX& mask) const override;
  void dae_initial_values(double t, const VectorX& state, VectorX& y, VectorX& yp) override;
  void state_from_dae(const VectorX& y, VectorX& state) const override { state = y.head(system_.size()); }
  void residual(double t, const VectorX& y, const VectorX& yp, VectorX& r) override;
  bool jacobian(double t, const VectorX& y, const VectorX& yp, MatrixX& residual_y, MatrixX& residual_yp) override;
  /// The loops' blocks (J's rows and columns) from the last residual's J, when a row of it
  /// has turned by more than 1 % of the row's largest entry since they were written.
  bool refresh_jacobian(MatrixX& residual_y) noexcept override;
  std::string describe_component(int index) const override;
  void algebraic_constraint_scales(VectorX& scale) const override;
  StateDiagnosis diagnose_state(double t, const VectorX& y) override {
    return system_.diagnose_state(t, y.head(system_.size()));
  }
  FastestMode fastest_mode(double t, const VectorX& y) override {
    return find_fastest_mode(system_, t, y.head(system_.size()));
  }
  // Joint stops (joint_stop_events.hpp): a free stop's gap, an active stop's multiplier.
  int event_count() const override { return stop_events_.count(); }
  void event_values(double t, const VectorX& y, Eigen::Ref<VectorX> g) override;
  void start_events(double t, VectorX& state) override { stop_events_.start(t, state); }
  bool handle_events(double t, const VectorX& y, const std::vector<int>& found, VectorX& state) override;

 private:
  /// Constraint rows in the DAE: the independent ones at the initial state.
  int kept_rows() const { return static_cast<int>(rows_.size()); }
  /// N(q) and N+(q) at the system's configuration.
  void configuration_maps();
  /// Writes dF/dy's blocks that are J itself (scaled rows), for the kept rows' J.
  void write_constraint_blocks(const MatrixX& kept_jacobian, MatrixX& residual_y);

  MultibodySystem& system_;
  DynamicsDifferentiator differentiator_;
  JointStopEvents stop_events_;
  std::vector<int> rows_;  // constraint rows kept in the DAE (set by dae_initial_values)
  VectorX w_, qdot_, qdot_plus_, zdot_, vdot_, lambda_, ode_rate_, q_perturbed_;
  MatrixX N_, N_plus_;
  VectorX map_unit_, map_qdot_, map_qdot_zero_;  // workspaces of configuration_maps()
  MatrixX n_times_jt_mu_q_;                      // nq x nv, workspace of jacobian()
  MatrixX rows_jacobian_;  // J of the kept rows at the last residual
  MatrixX rows_jacobian_in_newton_matrix_;  // the J of dF/dy's blocks (write_constraint_blocks)
  VectorX constraint_;     // Phi of the kept rows
  VectorX position_row_scale_;  // (J J^T)_ii of the kept rows at the start
  VectorX equation_scale_;      // a constant per equation (dae_initial_values)
  DynamicsDerivatives derivatives_;
  GglDerivatives ggl_derivatives_;
};

}  // namespace heavesim
