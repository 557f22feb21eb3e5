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
  bool completed = false;
  std::unique_ptr<Data> scratch;  // the check's own stages, sized on the first sample
  try {
    const RunOutcome outcome =
        run_case("cases/c4_irregular_waves/h1_active_hydraulic_3h.yaml", {}, [&](double t, const MultibodySystem& system) {
          const Model& model = system.model();
          if (!scratch) scratch = std::make_unique<Data>(model);
          const VectorX& q = system.configuration();
          const VectorX& v = system.velocity();
          update_positions(model, *scratch, q);
          VectorX phi(model.num_constraint_rows), target(model.num_constraint_rows);
          MatrixX jacobian(model.num_constraint_rows, model.nv);
          constraint_residual(model, *scratch, q, t, phi);
          constraint_jacobian(model, *scratch, jacobian);
          constraint_velocity_target(model, t, target);
          position_drift = std::max(position_drift, phi.cwiseAbs().maxCoeff());
          velocity_drift = std::max(velocity_drift, (jacobian * v - target).cwiseAbs().maxCoeff());
          ++samples;
        });
    completed = outcome.completed;
  } catch (const NumericalError&) {
  }
  if (!completed) position_drift = velocity_drift = std::numeric_limits<double>::infinity();
  const std::string subject = "H1 rig, 3 h JONSWAP, loop, IDA 1e-4 (" + std::to_string(samples) + " samples)";
  return {{"L4", subject, "max |Phi| over the run [m or rad]", position_drift, 1e-8},
          {"L4", subject, "max |J v - nu| over the run [m/s or rad/s]", velocity_drift, 1e-8}};
}

}  // namespace heavesim::validation
