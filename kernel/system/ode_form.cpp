#include "kernel/system/ode_form.hpp"

#include <cstdio>

#include "kernel/algorithms/configuration.hpp"
#include "kernel/algorithms/constraint_equations.hpp"
#include "kernel/algorithms/projection.hpp"

namespace heavesim {

OdeForm::OdeForm(MultibodySystem& system)
    : system_(system),
      q_(VectorX::Zero(system.model().nq)),
      v_(VectorX::Zero(system.model().nv)),
      row_selection_(system.model().nv, system.model().num_constraint_rows) {  // sized once: compute() reuses it
  row_selection_.setThreshold(constraint_rank_threshold);
}

void OdeForm::project(double t, VectorX& y) {
  const Model& model = system_.model();
  Data& data = system_.mutable_data();
  const SystemSettings& settings = system_.settings();
  q_ = y.head(model.nq);
  normalize_configuration(model, q_);
  if (model.has_constraints()) {
    v_ = y.segment(model.nq, model.nv);
    const ProjectionResult result =
        project_to_constraints(model, data, t, q_, v_, settings.projection_tolerance, settings.projection_iterations);
    if (!result.converged) {
      int worst = 0;
      data.constraint_residual.cwiseAbs().maxCoeff(&worst);
      char residual[32];
      std::snprintf(residual, sizeof residual, "%.3g", result.position_residual);
      std::string what = std::string("constraint projection did not converge: |Phi| = ") + residual + " after " +
                         std::to_string(result.iterations) + " iterations, worst at " +
                         describe_constraint_row(model, worst);
      // Where the projection stopped: rows becoming dependent there (a driver pulling
      // the loop beyond its reach) are the cause, not the step. The projection has
      // already failed, so a weaker loss (1e-2; with a driver, any) is the explanation.
      const StateDiagnosis loss = system_.constraint_loss(t, 1e-2);
      throw loss.explain(t, what,
                         !loss.empty()
                             ? "the loops are at a singular configuration: solver.integrator: hht carries a "
                               "mechanism through one; one that cannot move on (a dead centre) stops here"
                             : "the step was too large for the loop to be restored: reduce solver.step or the "
                               "tolerances, or check for a singular configuration");
    }
    y.segment(model.nq, model.nv) = v_;
    choose_constraint_rows();
  }
  y.head(model.nq) = q_;
}

void OdeForm::choose_constraint_rows() {
  const Model& model = system_.model();
  Data& data = system_.mutable_data();
  // The projection left J at the projected configuration, every row.
  if (constraint_rank_ < 0) {
    row_selection_.compute(data.constraint_jacobian.transpose());
    constraint_rank_ = static_cast<int>(row_selection_.rank());
    system_.remember_constraint_rank(constraint_rank_);
    data.constraint_rows_set_aside = constraint_rank_ < model.num_constraint_rows;
  }
  if (!data.constraint_rows_set_aside) return;
  row_selection_.compute(data.constraint_jacobian.transpose());
  data.constraint_row_used.setZero();
  const auto& pivots = row_selection_.colsPermutation().indices();
  for (int k = 0; k < constraint_rank_; ++k) data.constraint_row_used[pivots[k]] = 1.0;
}

}  // namespace heavesim
