// Stability stress of issue #3: the L1 slider-crank (cases/validation/slider_crank.yaml,
// a closed loop with a revolute loop joint) driven for three hours by a periodic crank
// torque tau(t) = tau0 sin(w t), the damper removed and the push off, so that
// mechanical energy changes only by the torque's work. The torque element carries the
// work W(t) = int tau theta' dt as an internal state integrated with the motion.
// Reported over every output sample (0.05 s):
//   constraint drift     max |Phi(q)| (loop-joint rows, m or rad)
//   velocity drift       max |J v|
//   energy balance drift max |E(t) - E(0) - W(t)|, E = kinetic + spring potential,
//                        absolute [J] and relative to the largest kinetic energy.
//
//   build/bench/heavesim_loop_stress [ida|hht|dopri5] [duration_s] [tolerance_or_step]
#include <time.h>

#include <cmath>
#include <cstdio>
#include <string>

#include <fmt/format.h>

#include "app/run/simulation_run.hpp"
#include "app/scene/scene.hpp"
#include "kernel/algorithms/energy.hpp"
#include "kernel/algorithms/constraint_equations.hpp"
#include "validation/checks/validation_suite.hpp"

namespace heavesim::bench {
namespace {

/// tau(t) = amplitude sin(frequency t) [N m] on the crank's revolute coordinate; state:
/// the work done [J], dW/dt = tau(t) theta'(t).
class PeriodicCrankTorque final : public ForceElement {
 public:
  PeriodicCrankTorque(const Model& model, int crank_joint, double amplitude, double frequency)
      : v_index_(model.joints[crank_joint].v_index),
        crank_link_(crank_joint),  // joints[i] moves links[i]
        amplitude_(amplitude),
        frequency_(frequency) {}
  const std::string& name() const override { return name_; }
  int state_size() const override { return 1; }
  void initial_state(Eigen::Ref<VectorX> z) const override { z.setZero(); }
  void apply(double t, const Model&, const Data&, Eigen::Ref<const VectorX>, AppliedForces& forces) const override {
    forces.joint_force[v_index_] += torque(t);
  }
  void state_derivative(double t, const Model&, const Data& data, Eigen::Ref<const VectorX>,
                        Eigen::Ref<VectorX> zdot) const override {
    // The crank turns about world z at a fixed pivot: theta' is its angular velocity's z.
    zdot[0] = torque(t) * data.velocity_world[crank_link_].angular().z();
  }

 private:
  double torque(double t) const { return amplitude_ * std::sin(frequency_ * t); }
  std::string name_ = "periodic_torque";
  int v_index_, crank_link_;
  double amplitude_, frequency_;
};

double cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

}  // namespace
}  // namespace heavesim::bench

int main(int argc, char** argv) {
  using namespace heavesim;
  const std::string method = argc > 1 ? argv[1] : "ida";
  const double duration = argc > 2 ? std::stod(argv[2]) : 10800.0;
  const double accuracy = argc > 3 ? std::stod(argv[3]) : (method == "hht" ? 1e-3 : 1e-8);
  const double spring_stiffness = 1.0, rest_length = 1.0;  // N/m, m: the case's spring

  std::vector<std::string> overrides = {"solver.integrator=" + method, fmt::format("solver.t_end={}", duration),
                                        "output.interval=0.05", "forces[spring].damping=0",
                                        "forces[push].force=[0, 0, 0]"};
  if (method == "hht") {
    overrides.insert(overrides.end(), {fmt::format("solver.step={}", accuracy), "solver.rtol=1e-10", "solver.atol=1e-10"});
  } else {
    overrides.insert(overrides.end(), {fmt::format("solver.rtol={}", accuracy), fmt::format("solver.atol={}", accuracy)});
  }
  const CaseDefinition definition =
      load_case(validation::project_file("cases/validation/slider_crank.yaml"), overrides);
  Scene scene = build_scene(definition);
  MultibodySystem& system = *scene.system;
  const Model& model = system.model();
  // 0.6 N m at 0.7 rad/s: the crank rocks and now and then turns over, through the
  // spring's potential well, for the whole record.
  system.add_force_element(std::make_unique<bench::PeriodicCrankTorque>(model, model.joint_index("crank_pivot"), 0.6, 0.7));
  scene.initial_state = system.initial_state(scene.initial_state.head(model.nq), scene.initial_state.segment(model.nq, model.nv));
  const int work_index = system.size() - 1;

  const int crank = model.link_index("crank"), rod = model.link_index("rod");
  const auto spring_energy = [&] {
    // The spring's ends in the bodies' frames (the case's point_a, point_b), to world.
    const auto world_point = [&](int link, const Vector3& point_body) {
      return system.data().X_world_link[link].act_point(model.links[link].X_link_body.act_point(point_body));
    };
    const Vector3 a = world_point(crank, Vector3(0.25, 0.0, 0.0));
    const Vector3 b = world_point(rod, Vector3(-0.5, 0.0, 0.0));
    const double stretch = (b - a).norm() - rest_length;
    return 0.5 * spring_stiffness * stretch * stretch;
  };
  VectorX phi(model.num_constraint_rows);
  double max_phi = 0.0, max_jv = 0.0, max_balance = 0.0, max_kinetic = 0.0, initial_energy = 0.0, max_angle = 0.0;
  long samples = 0;
  std::unique_ptr<Integrator> integrator = make_integrator(definition.solver.integrator, *scene.system);
  const double start = bench::cpu_seconds();
  const RunOutcome outcome =
      run_simulation(scene, definition.solver, definition.output.interval, *integrator, [&](double t, const VectorX& y) {
        system.evaluate(t, y, false);
        constraint_residual(model, system.data(), y.head(model.nq), t, phi);
        max_phi = std::max(max_phi, phi.cwiseAbs().maxCoeff());
        max_jv = std::max(max_jv, (system.data().constraint_jacobian * y.segment(model.nq, model.nv)).cwiseAbs().maxCoeff());
        const double kinetic = kinetic_energy(model, system.data());
        const double energy = kinetic + spring_energy();
        if (samples == 0) initial_energy = energy;
        max_kinetic = std::max(max_kinetic, kinetic);
        max_balance = std::max(max_balance, std::abs(energy - initial_energy - y[work_index]));
        max_angle = std::max(max_angle, std::abs(y[0] - M_PI / 2));
        ++samples;
        return true;
      });
  const double cpu = bench::cpu_seconds() - start;
  fmt::print("slider-crank, periodic crank torque 0.6 sin(0.7 t) N m, {} {} = {:g}, {:g} s ({} samples): {}\n", method,
             method == "hht" ? "h" : "rtol = atol", accuracy, duration, samples, outcome.completed ? "completed" : "INCOMPLETE");
  fmt::print("  max |Phi|               {:.3e} (m or rad)\n", max_phi);
  fmt::print("  max |J v|               {:.3e} (m/s or rad/s)\n", max_jv);
  fmt::print("  max |E - E0 - W|        {:.3e} J ({:.3e} of the largest kinetic energy {:.4f} J)\n", max_balance,
             max_balance / max_kinetic, max_kinetic);
  fmt::print("  largest crank excursion {:.2f} rad from the start\n", max_angle);
  fmt::print("  steps {}, evaluations {}, Jacobians {}, CPU {:.2f} s\n", outcome.statistics.steps,
             outcome.statistics.rhs_evaluations, outcome.statistics.jacobian_evaluations, cpu);
  return outcome.completed ? 0 : 3;
}
