// Static equilibrium (kernel/analysis/static_equilibrium.hpp, `initial: static`,
// `heavesim equilibrium`) and the `body_load` force kind, against closed forms written
// here: a pendulum's bob under a follower load (sin q = -F/(m g)) and under a world
// load (tan q = -F/(m g)); the hanging and the inverted pendulum's w^2 = +-m g l / I_O;
// a free body under gravity alone has no equilibrium (exit 3, naming the body and the
// direction); the equilibrium command's file and fragment, and a run from that
// fragment that stays at rest.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "app/case/case_definition.hpp"
#include "app/run/simulation_run.hpp"
#include "app/scene/scene.hpp"
#include "kernel/algorithms/joint_reactions.hpp"
#include "tests/app/h5_file.hpp"
#include "tests/test_support.hpp"

namespace heavesim {
namespace {

constexpr double m = 2.0, l = 1.5, g = 9.81, inertia = 1e-3;  // tests/cases/statics_pendulum.yaml
const std::string pendulum_case = "tests/cases/statics_pendulum.yaml";

Scene rest_scene(const std::string& relative_path, const std::vector<std::string>& overrides) {
  const CaseDefinition definition = load_case(testing::source_path(relative_path), overrides);
  return build_scene(definition);
}

double pivot_angle(const Scene& scene) { return scene.initial_state[0]; }

// Solved to equilibrium.tolerance = 1e-13 of the largest load (m g = 19.6 N): the
// moment residual is below 2e-12 N m, an angle error below 2e-12 / (m g l) ~ 1e-13 rad;
// 1e-11 leaves room for the differenced stiffness's effect on the last Newton step.
constexpr double angle_tolerance = 1e-11;

TEST(Statics, FollowerLoadOnAPendulumTipBalancesGravityBySinQ) {
  const Scene scene = rest_scene(pendulum_case, {});
  EXPECT_NEAR(pivot_angle(scene), -std::asin(0.3), angle_tolerance);
  EXPECT_EQ(scene.equilibrium->stability, EquilibriumStability::stable);
}

TEST(Statics, WorldLoadOnAPendulumTipBalancesGravityByTanQ) {
  const Scene scene = rest_scene(pendulum_case, {"forces[push].frame=world"});
  EXPECT_NEAR(pivot_angle(scene), -std::atan(0.3), angle_tolerance);
}

TEST(Statics, HangingPendulumIsStableWithItsSmallOscillationFrequency) {
  const Scene scene = rest_scene(pendulum_case, {"forces[push].force=[0, 0, 0]"});
  EXPECT_NEAR(pivot_angle(scene), 0.0, angle_tolerance);
  EXPECT_EQ(scene.equilibrium->stability, EquilibriumStability::stable);
  // w^2 = m g l / (m l^2 + I); the stiffness is analytic here (gravity through dID/dq).
  const double expected = m * g * l / (m * l * l + inertia);
  EXPECT_NEAR(scene.equilibrium->lowest_squared_frequency, expected, 1e-9 * expected);
}

TEST(Statics, InvertedPendulumIsAnUnstableEquilibrium) {
  const Scene scene = rest_scene(pendulum_case, {"forces[push].force=[0, 0, 0]", "joints[pivot].initial.q=3.0"});
  EXPECT_NEAR(std::abs(pivot_angle(scene)), M_PI, angle_tolerance);
  EXPECT_EQ(scene.equilibrium->stability, EquilibriumStability::unstable);
  const double expected = -m * g * l / (m * l * l + inertia);
  EXPECT_NEAR(scene.equilibrium->lowest_squared_frequency, expected, 1e-9 * std::abs(expected));
}

TEST(Statics, BodyLoadCoupleInTheWorldFrameTurnsThePendulumBySinQ) {
  // A couple C about the pivot axis balances m g l sin q; the couple is the same in
  // either frame here (the axis does not turn), so both frames give sin q = C / (m g l)
  // with the sign of the joint axis: a couple about -y raises the bob towards +x.
  for (const char* frame : {"world", "body"}) {
    SCOPED_TRACE(frame);
    const Scene scene = rest_scene(pendulum_case, {"forces[push].force=[0, 0, 0]",
                                                   std::string("forces[push].frame=") + frame,
                                                   "forces[push].moment=[0, -0.25*m*9.81*l, 0]"});
    EXPECT_NEAR(pivot_angle(scene), -std::asin(0.25), angle_tolerance);
  }
}

TEST(Statics, OverconstrainedParallelogramPushedSidewaysBalancesByTheVirtualWork) {
  // cases/validation/overconstrained_four_bar.yaml (10 loop rows, 7 redundant): three
  // 1 kg cranks of 1 m (CoM at 0.5 m) and a 2 kg coupler that translates with the tips.
  // A world force F along x on the coupler: V = -3.5 g cos(theta) - F sin(theta), so
  // tan(theta) = F / (3.5 g); the three pivots' reactions sum to (-F, 5 g, 0).
  constexpr double force = 10.0, gravity = 9.81;
  const Scene scene = rest_scene("cases/validation/overconstrained_four_bar.yaml",
                                 {"initial=static", "equilibrium={tolerance: 1e-13}",
                                  "forces=[{name: push, type: body_load, body: coupler, frame: world, force: [10, 0, 0]}]"});
  const Model& model = *scene.model;
  const double expected = std::atan(force / (3.5 * gravity));
  for (const char* pivot : {"pivot0", "pivot1", "pivot2"})
    EXPECT_NEAR(scene.initial_state[model.joints[model.joint_index(pivot)].q_index], expected, angle_tolerance) << pivot;
  EXPECT_NEAR(scene.initial_state[model.joints[model.joint_index("tip0")].q_index], -expected, angle_tolerance);
  EXPECT_EQ(scene.equilibrium->stability, EquilibriumStability::stable);
  scene.system->evaluate(0.0, scene.initial_state, true);
  Vector3 total = Vector3::Zero();
  for (const char* pivot : {"pivot0", "pivot1", "pivot2"})
    total += joint_reaction(model, scene.system->data(), model.joint_index(pivot)).force_world;
  EXPECT_LT((total - Vector3(-force, 5.0 * gravity, 0.0)).norm(), 1e-9 * 5.0 * gravity);
}

TEST(Statics, FreeBodyUnderGravityAloneHasNoEquilibriumAndTheErrorNamesIt) {
  const testing::CommandResult result = testing::run_command_line(
      testing::heavesim_binary() + " equilibrium " + testing::source_path("tests/cases/statics_free_body.yaml") +
      " -o " + temporary("statics_free_body.h5"));
  EXPECT_EQ(result.exit_code, 3) << result.output;
  EXPECT_NE(result.output.find("no static equilibrium"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("body 'block'"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("world force (0, 0, -98.1) N"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("suggestion"), std::string::npos) << result.output;
}

TEST(Statics, EquilibriumCommandWritesOneSampleAndAFragmentARunStaysAtRestFrom) {
  const std::string output = temporary("statics_crane.h5");
  const std::string fragment = temporary("statics_crane_rest.yaml");
  const std::string crane = testing::source_path("cases/statics/spring_crane.yaml");
  const testing::CommandResult result = testing::run_command_line(testing::heavesim_binary() + " equilibrium " + crane +
                                                                  " -o " + output + " --write-initial " + fragment);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("stability: stable"), std::string::npos) << result.output;
  {
    const H5File file(output);
    ASSERT_TRUE(file.ok());
    EXPECT_EQ(file.string_attribute("/", "analysis"), "equilibrium");
    EXPECT_EQ(file.long_attribute("/", "complete"), 1);
    EXPECT_EQ(file.shape("/time")[0], 1u);
  }
  // A case that includes the crane, then the fragment, starts from the joints' values
  // (initial: given) and stays there: the rest state is an equilibrium of the run too.
  const std::string wrapper = temporary("statics_crane_from_fragment.yaml");
  std::ofstream(wrapper) << "include: [" << crane << ", " << fragment << "]\ninitial: given\n";
  const CaseDefinition definition = load_case(wrapper, {});
  Scene scene = build_scene(definition);
  const double q0 = scene.initial_state[0];
  EXPECT_NEAR(q0, 0.7903925263208779, 1e-9);  // the elevation of validation row S1
  std::unique_ptr<Integrator> integrator = make_integrator(definition.solver.integrator, *scene.system);
  double drift = 0.0;
  run_simulation(scene, definition.solver, definition.output.interval, *integrator,
                 [&](double, const VectorX& y) {
                   drift = std::max(drift, std::abs(y[0] - q0));
                   return true;
                 });
  // The fragment's 15 digits and the 1e-13 residual leave accelerations of ~1e-12
  // rad/s^2: over 1 s the boom moves far less than 1e-9 rad.
  EXPECT_LT(drift, 1e-9);
}

// gas_pressure: balance counts what a loop carries (tests/cases/statics_lever_compensator.yaml):
// the stroke holds F = m_s g + m_b g c / a (moments about the beam's pin), so
// p0 = p_atm + F / A at the initial stroke s = 0 (V = V0: mid-stroke), and the initial
// state is then the rest state. Counting the stroke's own coordinate only (m_s g) would
// let the beam fall onto the end stop.
TEST(Statics, BalancePressureCountsTheLoadALoopBringsToTheStroke) {
  const Scene scene = rest_scene("tests/cases/statics_lever_compensator.yaml", {});
  constexpr double beam_mass = 2000.0, slider_mass = 300.0, c = 1.5, a = 0.6, area = 0.05;
  const double stroke_force = slider_mass * g + beam_mass * g * c / a;  // N
  const double atmospheric = 101325.0;                                  // Pa, the default
  ASSERT_EQ(scene.summarised.pneumatic_compensators.size(), 1u);
  const double pressure = scene.summarised.pneumatic_compensators[0].element->parameters().gas_pressure;
  EXPECT_NEAR(pressure, atmospheric + stroke_force / area, 1e-9 * pressure);
  // The equilibrium from the assembled guess stays where it started.
  EXPECT_NEAR(scene.initial_state[0], 0.0, 1e-10);  // pin, rad
  EXPECT_NEAR(scene.initial_state[1], 0.0, 1e-10);  // stroke, m
}

}  // namespace
}  // namespace heavesim
