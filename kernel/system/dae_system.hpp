#pragma once
// What IDA integrates: an implicit system F(t, y, y') = 0 with some components
// algebraic. A system that is naturally an ODE (OdeSystem) is wrapped as
// F = y' - f(t, y) by OdeResidual; a multibody model with closed loops provides its
// own stabilized index-2 form (MultibodySystem, Gear-Gupta-Leimkuhler).
//
// The integrator-facing state stays the ODE state of OdeSystem; a DAE may carry
// extra algebraic unknowns (multipliers) that it maps in and out.
#include <vector>

#include "kernel/system/ode_system.hpp"

namespace heavesim {

class DaeSystem : public FailureDiagnosis {
 public:
  virtual ~DaeSystem() = default;
  virtual int dae_size() const = 0;
  /// 1 for differential components, 0 for algebraic ones (excluded from IDA's error test).
  virtual void differential_mask(VectorX& mask) const = 0;
  /// Consistent (y, y') at time t for the ODE state `state`.
  virtual void dae_initial_values(double t, const VectorX& state, VectorX& y, VectorX& yp) = 0;
  /// The ODE state contained in y.
  virtual void state_from_dae(const VectorX& y, VectorX& state) const = 0;
  virtual void residual(double t, const VectorX& y, const VectorX& yp, VectorX& r) = 0;
  /// For each algebraic component i, s_i such that an error d in it moves the residual
  /// of its constraint by about h s_i d over a step h (0 for differential components
  /// and algebraic ones without a constraint): the integrator weighs it by
  /// h s_i / (constraint tolerance) in Newton's test. Default: none.
  virtual void algebraic_constraint_scales(VectorX& scale) const { scale.setZero(dae_size()); }
  /// The two parts of IDA's Newton matrix dF/dy + cj dF/dy': dF/dy in `residual_y` and
  /// dF/dy' in `residual_yp` (apart, so that the integrator re-forms the matrix for a new
  /// cj without evaluating them again). Returns false to let the integrator approximate
  /// the matrix.
  virtual bool jacobian(double /*t*/, const VectorX& /*y*/, const VectorX& /*yp*/, MatrixX& /*residual_y*/,
                        MatrixX& /*residual_yp*/) {
    return false;
  }
  /// Brings the blocks of `residual_y` (the dF/dy of the last jacobian() call) that are
  /// cheap to evaluate up to the state of the last residual() call where they have changed
  /// enough to slow Newton's iteration, keeping the costly ones; true when it changed any.
  /// IDA with position multipliers calls it before each linear solve and re-forms the
  /// Newton matrix when it returns true (reforming_linear_solver.hpp). Called from
  /// SUNDIALS' C code: it must not throw. Default: nothing.
  virtual bool refresh_jacobian(MatrixX& /*residual_y*/) noexcept { return false; }

  // --- events (Simbody's event triggers and handlers): functions g_i(t, y) whose fall
  // through zero the integrator locates, and what happens there ---
  /// How many event functions there are (0: none).
  virtual int event_count() const { return 0; }
  /// g(t, y) (event_count values): an event happens where one falls from > 0 to <= 0.
  virtual void event_values(double /*t*/, const VectorX& /*y*/, Eigen::Ref<VectorX> /*g*/) {}
  /// Before the first step from the ODE state `state` at t: events that hold already (a
  /// body resting on a stop) take effect; `state` may change.
  virtual void start_events(double /*t*/, VectorX& /*state*/) {}
  /// At t, where the events with found[i] != 0 fell through zero (y: the DAE's values
  /// there): the ODE state to go on from, in `state`. Returns true when the integration
  /// must restart from it (a velocity jump, a changed set of constraints).
  virtual bool handle_events(double /*t*/, const VectorX& /*y*/, const std::vector<int>& /*found*/,
                             VectorX& /*state*/) {
    return false;
  }
};

/// F(t, y, y') = y' - f(t, y) for an OdeSystem; every component differential.
class OdeResidual : public DaeSystem {
 public:
  explicit OdeResidual(OdeSystem& system) : system_(system), f_(system.size()) {}
  int dae_size() const override { return system_.size(); }
  void differential_mask(VectorX& mask) const override { mask.setOnes(system_.size()); }
  void dae_initial_values(double t, const VectorX& state, VectorX& y, VectorX& yp) override {
    y = state;
    yp.resize(state.size());
    system_.derivative(t, y, yp);
  }
  void state_from_dae(const VectorX& y, VectorX& state) const override { state = y; }
  std::string describe_component(int index) const override { return system_.describe_component(index); }
  StateDiagnosis diagnose_state(double t, const VectorX& y) override { return system_.diagnose_state(t, y); }
  FastestMode fastest_mode(double t, const VectorX& y) override { return system_.fastest_mode(t, y); }
  void residual(double t, const VectorX& y, const VectorX& yp, VectorX& r) override {
    system_.derivative(t, y, f_);
    r = yp - f_;
  }

 private:
  OdeSystem& system_;
  VectorX f_;
};

}  // namespace heavesim
