// The stage marker in Data: which stages are current, for which evaluation and time;
// a read of stages that a later evaluation overwrote (or that were never computed) is
// caught by require_stages.
#include <gtest/gtest.h>

#include <stdexcept>

#include "kernel/algorithms/inverse_dynamics.hpp"
#include "kernel/algorithms/kinematics.hpp"
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

TEST(StageMarker, NewVelocitiesOnTheSamePositionsAreANewEvaluation) {
  MultibodySystem system(samples::vertical_slider(10.0));
  const VectorX y = system.initial_state(VectorX::Constant(1, 0.2), VectorX::Constant(1, 0.1));
  system.evaluate(0.5, y, true);
  const long evaluation = system.data().stages.evaluation;
  // Same q, another v: the placements stay, but what was derived from the old speeds
  // (accelerations, reactions) is gone and an old reader must see it.
  VectorX other = y;
  other[1] = -0.3;
  system.compute_kinematics(other);
  const StageMarker& stages = system.data().stages;
  EXPECT_EQ(stages.current, kinematics);
  EXPECT_NE(stages.evaluation, evaluation);
  EXPECT_THROW(require_stages(system.data(), kinematics, 0.5, evaluation), std::logic_error);
}

TEST(StageMarker, InverseDynamicsOverwritesTheAccelerationStage) {
  MultibodySystem system(samples::vertical_slider(10.0));
  const VectorX y = system.initial_state(VectorX::Constant(1, 0.2), VectorX::Constant(1, 0.1));
  system.evaluate(0.5, y, true);
  Data& data = system.mutable_data();
  // An inverse-dynamics pass for the caller's own acceleration rewrites the link
  // accelerations and joint wrenches: neither the acceleration nor the reaction stage is
  // the evaluation's any more.
  inverse_dynamics(system.model(), data, VectorX::Constant(1, 3.0));
  EXPECT_EQ(data.stages.current, kinematics);
}

TEST(StageMarker, VelocitiesNeedTheirPositions) {
  const auto model_pointer = samples::vertical_slider(10.0);
  const Model& model = *model_pointer;
  Data data(model);
  EXPECT_THROW(update_velocities(model, data, VectorX::Zero(1), VectorX::Zero(1)), std::logic_error);
  update_positions(model, data, VectorX::Zero(1));
  EXPECT_NO_THROW(update_velocities(model, data, VectorX::Zero(1), VectorX::Zero(1)));
}

}  // namespace
}  // namespace heavesim
