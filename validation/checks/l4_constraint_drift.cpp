// L4: constraint drift over a long run. The 3-hour H1 rig in a JONSWAP sea
// (cases/c4_irregular_waves/h1_active_hydraulic_3h.yaml: two passive cylinders and an
// active one on a crown block closed by a loop, IDA at rtol = atol = 1e-4, the
// case as shipped) must keep the loop closed: max |Phi| and max |J v - nu| over every
// output sample (0.5 s, 21601 samples), computed here from the recorded q and v on a
// Data of the check's own, against 1e-8 (m or rad, m/s or rad/s). IDA holds Phi = 0 to
// solver.constraint_tolerance (1e-10) through the position multipliers' weight in
// Newton's test (kernel/integrators/ida_integrator.cpp), independently of rtol.
#include <algorithm>
#include <limits>
#include <memory>

#include "kernel/algorithms/constraint_equations.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "validation/checks/validation_suite.hpp"

namespace heavesim::validation {

std::vector<ValidationRow> check_l4_constraint_drift() {
  double position_drift = 0.0, velocity_drift = 0.0;
  long samples = 0;
  std::unique_ptr<Data> scratch;  // the check's own stages and constraint terms, sized on the first sample
  const RunOutcome outcome = run_case_to_failure(
      "cases/c4_irregular_waves/h1_active_hydraulic_3h.yaml", {}, [&](double t, const MultibodySystem& system) {
        const Model& model = system.model();
        if (!scratch) scratch = std::make_unique<Data>(model);
        Data& data = *scratch;
        const VectorX& q = system.configuration();
        update_positions(model, data, q);
        constraint_residual(model, data, q, t, data.constraint_residual);
        constraint_jacobian(model, data, t, data.constraint_jacobian);
        constraint_velocity_target(model, data, t, data.constraint_velocity_target);
        data.constraint_bias.noalias() = data.constraint_jacobian * system.velocity();  // workspace: J v
        data.constraint_bias -= data.constraint_velocity_target;
        position_drift = std::max(position_drift, data.constraint_residual.cwiseAbs().maxCoeff());
        velocity_drift = std::max(velocity_drift, data.constraint_bias.cwiseAbs().maxCoeff());
        ++samples;
      });
  if (!outcome.completed) position_drift = velocity_drift = std::numeric_limits<double>::infinity();
  const std::string subject = "H1 rig, 3 h JONSWAP, loop, IDA 1e-4 (" + std::to_string(samples) + " samples)";
  return {{"L4", subject, "max |Phi| over the run [m or rad]", position_drift, 1e-8},
          {"L4", subject, "max |J v - nu| over the run [m/s or rad/s]", velocity_drift, 1e-8}};
}

}  // namespace heavesim::validation
