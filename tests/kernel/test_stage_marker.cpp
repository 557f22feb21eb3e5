// The stage marker in Data: which stages are current, for which evaluation and time;
// a read of stages that a later evaluation overwrote (or that were never computed) is
// caught by require_stages.
#include <gtest/gtest.h>

#include <stdexcept>

#include "kernel/system/multibody_system.hpp"
#include "samples/oscillators.hpp"

namespace heavesim {
namespace {

constexpr unsigned kinematics = StageMarker::positions | StageMarker::velocities;
constexpr unsigned dynamics = kinematics | StageMarker::accelerations;

TEST(StageMarker, EvaluateMarksItsStagesAndTime) {
  MultibodySystem system(samples::vertical_slider(10.0));
  const VectorX y = system.initial_state(VectorX::Constant(1, 0.2), VectorX::Constant(1, 0.1));
  system.evaluate(0.5, y, false);
  const StageMarker& stages = system.data().stages;
  EXPECT_EQ(stages.current, dynamics);
  EXPECT_EQ(stages.time, 0.5);
  system.evaluate(0.5, y, true);
  EXPECT_EQ(stages.current, dynamics | StageMarker::reactions);
}

TEST(StageMarker, AStaleReadIsDetected) {
  MultibodySystem system(samples::vertical_slider(10.0));
  const VectorX y = system.initial_state(VectorX::Constant(1, 0.2), VectorX::Constant(1, 0.1));
  system.evaluate(0.5, y, false);
  const long evaluation = system.data().stages.evaluation;
  EXPECT_NO_THROW(require_stages(system.data(), dynamics, 0.5, evaluation));
  // Never computed in this evaluation; another time.
  EXPECT_THROW(require_stages(system.data(), StageMarker::reactions, 0.5, evaluation), std::logic_error);
  EXPECT_THROW(require_stages(system.data(), dynamics, 0.4, evaluation), std::logic_error);
  // Another evaluation (the same state and time) overwrites the stages: the old reader is stale.
  system.evaluate(0.5, y, false);
  EXPECT_THROW(require_stages(system.data(), dynamics, 0.5, evaluation), std::logic_error);
  // A kinematics-only evaluation (as the implicit forms' projections do) has no accelerations.
  system.compute_kinematics(y);
  EXPECT_THROW(require_stages(system.data(), StageMarker::accelerations, system.data().stages.time,
                              system.data().stages.evaluation),
               std::logic_error);
}

}  // namespace
}  // namespace heavesim
