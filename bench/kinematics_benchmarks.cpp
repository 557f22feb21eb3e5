// Kinematic analysis (docs/physics/kinematics.md):
//  * kinematic_sweep: the MKSim slider-crank (cases/kinematics/mksim_slider_crank.yaml)
//    analysed at 10,001 time points (t = 0..10 s every 1 ms): positions (Newton from the
//    second-order predictor), velocities, accelerations and the inverse dynamics of the
//    motion (driver force), as `heavesim kinematics` does without writing a file; and the
//    kernel's solves alone (analyse_time_point).
//  * constraint_jacobian / constraint_bias per loop joint: a chain of 16 bodies on free
//    joints from the ground, consecutive bodies tied by loop joints of one kind, at a
//    random state; time per loop joint (the counter `per_joint_ns`).
// Run: build/bench/heavesim_kinematics_bench.
#include <benchmark/benchmark.h>

#include <random>

#include <fmt/format.h>

#include "app/run/kinematic_run.hpp"
#include "app/scene/scene.hpp"
#include "kernel/algorithms/constraint_equations.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/model/model_builder.hpp"

namespace heavesim::bench {
namespace {

constexpr const char* slider_crank = HEAVESIM_SOURCE_DIR "/cases/kinematics/mksim_slider_crank.yaml";
const std::vector<std::string> ten_thousand_points = {"output.interval=0.001"};

void kinematic_sweep(benchmark::State& state) {
  const CaseDefinition definition = load_case(slider_crank, ten_thousand_points);
  long points = 0, iterations = 0;
  for (auto _ : state) {
    state.PauseTiming();
    Scene scene = build_scene(definition);
    state.ResumeTiming();
    const KinematicOutcome outcome =
        run_kinematics(scene, definition, false, [](double, const VectorX&, const KinematicPoint&) { return true; });
    points = outcome.points;
    iterations = outcome.newton_iterations;
  }
  state.counters["points"] = static_cast<double>(points);
  state.counters["newton_per_point"] = static_cast<double>(iterations) / static_cast<double>(points);
  state.counters["per_point_us"] =
      benchmark::Counter(static_cast<double>(points) * 1e-6, benchmark::Counter::kIsIterationInvariantRate |
                                                                 benchmark::Counter::kInvert);
}
BENCHMARK(kinematic_sweep)->Unit(benchmark::kMillisecond);

void kinematic_solves_only(benchmark::State& state) {
  const CaseDefinition definition = load_case(slider_crank, ten_thousand_points);
  const Scene scene = build_scene(definition);
  const Model& model = *scene.model;
  Data data(model);
  KinematicWorkspace workspace(model);
  const long intervals = output_interval_count(definition.solver, definition.output.interval);
  for (auto _ : state) {
    VectorX q = scene.initial_state.head(model.nq), v = VectorX::Zero(model.nv), a = VectorX::Zero(model.nv);
    double previous = 0.0;
    for (long k = 0; k <= intervals; ++k) {
      const double t = k * definition.output.interval;
      const KinematicPoint point =
          analyse_time_point(model, data, workspace, definition.kinematics, t, t - previous, q, v, a);
      benchmark::DoNotOptimize(point);
      previous = t;
    }
  }
  state.counters["points"] = static_cast<double>(intervals + 1);
}
BENCHMARK(kinematic_solves_only)->Unit(benchmark::kMillisecond);

/// 16 bodies on free joints; body i and i + 1 tied by a loop joint of `kind`.
Model loop_joint_chain(JointKind kind, int bodies) {
  ModelBuilder builder;
  for (int i = 0; i < bodies; ++i) {
    const std::string name = "body" + std::to_string(i);
    builder.add_body({name, Inertia(1.0, Vector3(0.1, 0.0, 0.0), Matrix3::Identity() * 0.1), std::nullopt});
    JointDefinition joint;
    joint.name = "free" + std::to_string(i);
    joint.kind = JointKind::free;
    joint.parent = "ground";
    joint.child = name;
    builder.add_joint(joint);
    if (i == 0) continue;
    LoopJointDefinition loop;
    loop.name = "loop" + std::to_string(i);
    loop.kind = kind;
    loop.axis = Vector3(0.0, 0.6, 0.8);
    loop.second_axis = Vector3(1.0, 0.0, 0.0);
    loop.parent = "body" + std::to_string(i - 1);
    loop.child = name;
    loop.X_parent_joint = Transform(Matrix3::Identity(), Vector3(0.5, 0.1, 0.0));
    loop.X_child_joint = Transform(Matrix3::Identity(), Vector3(-0.5, 0.0, 0.2));
    builder.add_loop_joint(loop);
  }
  return builder.build();
}

constexpr JointKind loop_kinds[] = {JointKind::fixed, JointKind::revolute, JointKind::prismatic,
                                    JointKind::cylindrical, JointKind::universal, JointKind::spherical};

/// A chain of `bodies` bodies tied by loop joints of the benchmark's kind (its range(0)),
/// at a random configuration (unit quaternions) and velocity: position and velocity
/// stages current, as the Jacobian and gamma read them.
struct LoopChainAtRandomState {
  static constexpr int bodies = 16;
  explicit LoopChainAtRandomState(const benchmark::State& state)
      : model(loop_joint_chain(loop_kinds[state.range(0)], bodies)), data(model) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    VectorX q = model.neutral_configuration();
    for (int k = 0; k < model.nq; ++k) q[k] += 0.3 * uniform(random);
    const VectorX v = VectorX::NullaryExpr(model.nv, [&](Eigen::Index) { return uniform(random); });
    update_positions(model, data, q);
    update_velocities(model, data, q, v);
  }
  Model model;
  Data data;
};

/// The label and the time per loop joint of a chain of `bodies` (bodies - 1 loop joints).
void report_per_loop_joint(benchmark::State& state, const Model& model, int bodies) {
  state.SetLabel(fmt::format("{} loop joints, {} rows",
                             joint_type_name(canonical_joint_type(loop_kinds[state.range(0)])),
                             model.num_constraint_rows));
  state.counters["per_joint_ns"] = benchmark::Counter(
      (bodies - 1) * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void jacobian_per_loop_joint(benchmark::State& state) {
  LoopChainAtRandomState chain(state);
  MatrixX J = MatrixX::Zero(chain.model.num_constraint_rows, chain.model.nv);
  for (auto _ : state) {
    constraint_jacobian(chain.model, chain.data, 0.0, J);
    benchmark::ClobberMemory();
  }
  report_per_loop_joint(state, chain.model, chain.bodies);
}
BENCHMARK(jacobian_per_loop_joint)->DenseRange(0, 5);

void gamma_per_loop_joint(benchmark::State& state) {
  LoopChainAtRandomState chain(state);
  VectorX gamma = VectorX::Zero(chain.model.num_constraint_rows);
  for (auto _ : state) {
    constraint_bias(chain.model, chain.data, 0.0, gamma);
    benchmark::DoNotOptimize(gamma.data());
  }
  report_per_loop_joint(state, chain.model, chain.bodies);
}
BENCHMARK(gamma_per_loop_joint)->DenseRange(0, 5);

}  // namespace
}  // namespace heavesim::bench

BENCHMARK_MAIN();
