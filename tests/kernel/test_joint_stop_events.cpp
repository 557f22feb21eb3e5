// Joint stops met by event location under IDA (kernel/system/joint_stop_events.hpp)
// against closed forms: a load dropped on a stop bounces with Newton's restitution at the
// impact times of free fall until its impacts are slower than the threshold, then rests
// with the stop carrying its weight; a load on a heaving floor lifts off where the
// floor falls away faster than g (the stop's force falls through zero) and lands again
// (a gap closing), as the piecewise closed form. IDA places each event to its
// tolerance, so the errors are those of the smooth integration, not of a time step.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "kernel/integrators/integrator.hpp"
#include "kernel/system/multibody_system.hpp"
#include "samples/contact_scenes.hpp"
#include "tests/kernel/heaving_support_reference.hpp"

// A namespace of its own: the unity build compiles this file together with others
// (top CMakeLists.txt), whose file-local names must not meet these.
namespace heavesim::test_joint_stop_events {
namespace {

constexpr double g = 9.81;

struct IdaRun {
  MultibodySystem system;
  std::unique_ptr<Integrator> integrator;
  int lift_q, lift_v, stop_row;
  explicit IdaRun(const samples::StopScene& scene)
      : system(scene.model),
        lift_q(scene.model->joints[scene.model->joint_index("lift")].q_index),
        lift_v(scene.model->nq + scene.model->joints[scene.model->joint_index("lift")].v_index),
        stop_row(scene.model->constraints.back().first_row) {
    IntegratorSettings settings;
    settings.method = IntegrationMethod::ida;
    settings.relative_tolerance = 1e-10;
    settings.absolute_tolerance = 1e-12;
    integrator = make_integrator(settings, system);
    integrator->initialize(0.0, system.initial_state(scene.q, scene.v));
  }
  double height() const { return integrator->state()[lift_q]; }
  double speed() const { return integrator->state()[lift_v]; }
  /// The stop's force at the integrator's state [N] (its multiplier; 0 while free).
  double stop_force() {
    system.evaluate(integrator->time(), integrator->state(), false);
    return system.data().constraint_active[stop_row] * system.data().constraint_multipliers[stop_row];
  }
};

TEST(JointStopEvents, DroppedLoadBouncesAtTheFreeFallImpactsAndComesToRest) {
  // From 0.5 m with e = 0.5: impacts at t1 = sqrt(2 h / g), then every 2 e^n v1 / g, each
  // leaving at e times its approach speed, until one approaches slower than 0.05 m/s
  // (v1 = 3.13 m/s: the 7th, at 0.049 m/s) and the load stays, the stop carrying m g.
  const double drop = 0.5, e = 0.5, mass = 200.0;
  IdaRun run(samples::load_on_heaving_floor({0.0, 1.0}, mass, e, drop));
  std::vector<double> impact_times;
  double t = std::sqrt(2 * drop / g), speed = g * t;
  while (speed > 0.05) {
    impact_times.push_back(t);
    t += 2 * e * speed / g;
    speed *= e;
  }
  impact_times.push_back(t);  // the last, plastic: at rest from here
  ASSERT_EQ(impact_times.size(), 7u);
  // The closed form between impacts: free fall from the last impact at e times its speed.
  const auto expected_height = [&](double time) {
    if (time < impact_times[0]) return drop - 0.5 * g * time * time;
    for (std::size_t k = 0; k + 1 < impact_times.size(); ++k)
      if (time < impact_times[k + 1]) {
        const double leave = e * g * impact_times[0] * std::pow(e, static_cast<double>(k)), s = time - impact_times[k];
        return leave * s - 0.5 * g * s * s;
      }
    return 0.0;
  };
  double worst = 0.0;
  for (double time = 0.01; time < impact_times.back() + 0.5; time += 0.01) {
    run.integrator->advance_to(time);
    worst = std::max(worst, std::abs(run.height() - expected_height(time)));
    EXPECT_GE(run.height(), -1e-12) << "t = " << time;  // never through the stop
  }
  EXPECT_LT(worst, 1e-10);  // m; measured 1.7e-12 at rtol 1e-10
  EXPECT_EQ(run.integrator->statistics().events, 7);  // one per impact, none spurious
  EXPECT_NEAR(run.stop_force(), mass * g, 1e-8 * mass * g);
  // At rest on the stop: zero to round-off far below the tolerances (5e-90 m/s measured
  // with IDA's Newton matrix kept across wide cj changes, exactly 0 with a new one each).
  EXPECT_LT(std::abs(run.speed()), 1e-14);
}

TEST(JointStopEvents, LoadOnAHeavingFloorLiftsOffAndLandsAsTheClosedForm) {
  // The floor heaves 1 m at 4 rad/s (16 m/s^2 peak, beyond g): the load lifts off where
  // the floor falls away faster than g -- the stop's force m (g + a_floor) falls through
  // zero, an event -- flies, and lands plastically (e = 0) where its gap closes, another
  // event. Against the piecewise closed form of the hoist line's test (offset 0).
  const samples::HeavingTip floor;
  const double mass = 2000.0;
  IdaRun run(samples::load_on_heaving_floor(floor, mass, 0.0, 0.0));
  testing::HeavingSupportReference reference(floor, 0.0);
  std::vector<double> times;
  for (double time = 0.005; time < 4.0; time += 0.005) times.push_back(time);
  const std::vector<double> expected = reference.load_height(times);
  ASSERT_GE(reference.contacts.size(), 2u);
  double worst = 0.0, worst_force = 0.0;
  for (std::size_t k = 0; k < times.size(); ++k) {
    run.integrator->advance_to(times[k]);
    const double height = reference.z_support(times[k]) + run.height();  // absolute
    worst = std::max(worst, std::abs(height - expected[k]));
    bool free = false;
    for (const auto& [from, to] : reference.free_phases) free |= times[k] > from && times[k] < to;
    const double force = run.stop_force();
    worst_force = std::max(worst_force, std::abs(force - (free ? 0.0 : mass * (g + reference.a_support(times[k])))));
  }
  // Measured: 6.1e-10 m and 4.3e-7 N (of 2e4 N), at rtol 1e-10.
  EXPECT_LT(worst, 1e-8);
  EXPECT_LT(worst_force, 1e-9 * mass * g);
  // An event at each landing, and at each lift-off from rest (the force falling through
  // zero); a landing where the floor already falls away faster than g is one event.
  long lift_offs = 0;
  for (const auto& [from, to] : reference.free_phases) {
    bool at_landing = false;
    for (const auto& contact : reference.contacts) at_landing |= contact.first == from;
    lift_offs += !at_landing;
  }
  EXPECT_EQ(run.integrator->statistics().events, static_cast<long>(reference.contacts.size()) + lift_offs);
}

}  // namespace
}  // namespace heavesim::test_joint_stop_events
