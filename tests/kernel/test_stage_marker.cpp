// The stage marker in Data: which stages are current, for which evaluation and time;
// a read of stages that a later evaluation overwrote (or that were never computed) is
// caught by require_stages.
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

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

TEST(StageMarker, EvaluationNumbersAreUniqueAcrossDataAndThreads) {
  // An element keeps what it computed under the evaluation number alone
  // (kernel/elements/evaluation_key.hpp): two Data, or two threads, must never hold the
  // same number for different stages; a copy holds its original's (the same stages).
  const auto model_pointer = samples::vertical_slider(10.0);
  const Model& model = *model_pointer;
  Data first(model), second(model);
  EXPECT_EQ(first.stages.evaluation, 0);  // no stage yet
  update_positions(model, first, VectorX::Constant(1, 0.1));
  update_positions(model, second, VectorX::Constant(1, 0.2));
  EXPECT_NE(first.stages.evaluation, second.stages.evaluation);
  EXPECT_NE(first.stages.evaluation, 0);
  const Data copy = first;
  EXPECT_EQ(copy.stages.evaluation, first.stages.evaluation);
  std::vector<long> numbers[2];
  auto evaluate_many = [&model](std::vector<long>& numbers) {
    Data data(model);
    for (int k = 0; k < 2000; ++k) {
      update_positions(model, data, VectorX::Constant(1, 1e-3 * k));
      numbers.push_back(data.stages.evaluation);
      update_velocities(model, data, VectorX::Constant(1, 1e-3 * k), VectorX::Zero(1));
      numbers.push_back(data.stages.evaluation);
    }
  };
  std::thread other(evaluate_many, std::ref(numbers[1]));
  evaluate_many(numbers[0]);
  other.join();
  std::set<long> seen{first.stages.evaluation, second.stages.evaluation};
  for (const std::vector<long>& list : numbers) seen.insert(list.begin(), list.end());
  EXPECT_EQ(seen.size(), 2u + numbers[0].size() + numbers[1].size());
}

}  // namespace
}  // namespace heavesim
