// The recording wrapper of a load on one body (app/scene/recorded_load.hpp): the loads it
// passes on are the wrapped element's, bit for bit, and its force and moment channels are
// the wrapped element's load on the body, whether apply() kept it at that evaluation or
// outputs() has to apply the element again (another Data, another time); the same for
// the linear restoring's potential energy, which reads back the displacement apply() took.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "app/scene/recorded_load.hpp"
#include "hydro/elements/linear_body_loads.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/system/multibody_system.hpp"
#include "samples/floating_bodies.hpp"

namespace heavesim {
namespace {

using hydro::BodyDamping;
using hydro::LinearRestoring;

struct RestoredHull {
  std::shared_ptr<const Model> model = samples::free_floating_body(
      "hull", Inertia(2e5, Vector3(0, 0, -1), Vector3(1e6, 2e6, 3e6).asDiagonal()), std::nullopt);
  int link = model->link_index("hull");
  Matrix6 stiffness;
  Vector6 pretension;
  RestoredHull() {
    // A full, non-symmetric stiffness: every displacement reaches every load component.
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) stiffness(i, j) = (i == j ? 5e5 : 1e4 * (1 + i - 0.5 * j));
    pretension << 1e3, -2e3, 3e6, 4e2, -5e2, 6e1;
  }
  std::unique_ptr<ForceElement> restoring() const {
    return std::make_unique<LinearRestoring>("restoring", link, stiffness, pretension, Transform::Identity());
  }
  /// The free joint at x, y, z [m], turned by yaw [rad] about the world z axis.
  VectorX configuration(double x, double y, double z, double yaw) const {
    VectorX q = model->neutral_configuration();
    q.head<3>() << x, y, z;
    q.segment<4>(3) << std::cos(yaw / 2), 0.0, 0.0, std::sin(yaw / 2);  // w, x, y, z
    return q;
  }
  /// xi = [x, y, z, 0, 0, yaw] of the pose above.
  static Vector6 displacement(double x, double y, double z, double yaw) {
    return (Vector6() << x, y, z, 0.0, 0.0, yaw).finished();
  }
  /// F = f0 - K xi: the channels' closed form ([force; moment about the body origin], world axes).
  Vector6 expected_load(double x, double y, double z, double yaw) const {
    return pretension - stiffness * displacement(x, y, z, yaw);
  }
  /// V = xi^T K xi / 2 - f0 . xi [J].
  double expected_energy(double x, double y, double z, double yaw) const {
    const Vector6 xi = displacement(x, y, z, yaw);
    return 0.5 * xi.dot(stiffness * xi) - pretension.dot(xi);
  }
};

void expect_channels(const std::vector<double>& values, const Vector6& load) {
  ASSERT_EQ(values.size(), 6u);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(values[i], load[i], 1e-9 * load.norm()) << "channel " << i;
}

TEST(RecordedLoad, ChannelsAreTheLoadWhetherKeptOrAppliedAgain) {
  const RestoredHull hull;
  MultibodySystem system(hull.model);
  auto wrapper = std::make_unique<RecordedLoad>(hull.restoring(), *hull.model, hull.link, nullptr);
  const RecordedLoad& recorded = *wrapper;
  system.add_force_element(std::move(wrapper));
  const VectorX v = VectorX::Constant(hull.model->nv, 0.1);
  const VectorX y = system.initial_state(hull.configuration(0.4, -0.3, -0.5, 0.05), v);
  VectorX ydot(system.size());
  std::vector<double> values(6);

  // Kept by apply() at this evaluation.
  system.state_derivative(2.0, y, ydot);
  recorded.outputs(2.0, system.model(), system.data(), VectorX(), values);
  expect_channels(values, hull.expected_load(0.4, -0.3, -0.5, 0.05));
  const double energy = hull.expected_energy(0.4, -0.3, -0.5, 0.05);
  EXPECT_NEAR(recorded.potential_energy(system.model(), system.data(), VectorX()), energy, 1e-9 * std::abs(energy));

  // Another Data the wrapper never applied on: applied again there.
  Data other(*hull.model);
  const VectorX q_other = hull.configuration(-1.0, 2.0, 0.7, -0.1);
  update_positions(*hull.model, other, q_other);
  update_velocities(*hull.model, other, q_other, v);
  other.stages.time = 2.0;
  recorded.outputs(2.0, system.model(), other, VectorX(), values);
  expect_channels(values, hull.expected_load(-1.0, 2.0, 0.7, -0.1));
  const double other_energy = hull.expected_energy(-1.0, 2.0, 0.7, -0.1);
  EXPECT_NEAR(recorded.potential_energy(system.model(), other, VectorX()), other_energy, 1e-9 * std::abs(other_energy));

  // Back on the system's evaluation: what apply() kept there still is its load.
  recorded.outputs(2.0, system.model(), system.data(), VectorX(), values);
  expect_channels(values, hull.expected_load(0.4, -0.3, -0.5, 0.05));

  // A new evaluation of the system at another pose: the channels follow it.
  const VectorX y_moved = system.initial_state(hull.configuration(0.1, 0.2, 0.3, 0.2), v);
  system.state_derivative(2.5, y_moved, ydot);
  recorded.outputs(2.5, system.model(), system.data(), VectorX(), values);
  expect_channels(values, hull.expected_load(0.1, 0.2, 0.3, 0.2));
  const double moved_energy = hull.expected_energy(0.1, 0.2, 0.3, 0.2);
  EXPECT_NEAR(recorded.potential_energy(system.model(), system.data(), VectorX()), moved_energy,
              1e-9 * std::abs(moved_energy));
}

TEST(RecordedLoad, PassesTheWrappedLoadOnBitForBit) {
  // A damping element on the same body first: the wrapper adds its load onto what is there.
  const RestoredHull hull;
  const Matrix6 damping = Matrix6::Identity() * 3e4;
  MultibodySystem bare(hull.model), wrapped(hull.model);
  bare.add_force_element(std::make_unique<BodyDamping>("damping", hull.link, damping));
  bare.add_force_element(hull.restoring());
  wrapped.add_force_element(std::make_unique<BodyDamping>("damping", hull.link, damping));
  wrapped.add_force_element(std::make_unique<RecordedLoad>(hull.restoring(), *hull.model, hull.link, nullptr));
  const VectorX y = bare.initial_state(hull.configuration(0.4, -0.3, -0.5, 0.05),
                                       (VectorX(6) << 0.02, -0.01, 0.3, 0.2, -0.1, 0.05).finished());
  VectorX bare_rates(bare.size()), wrapped_rates(wrapped.size());
  bare.state_derivative(1.0, y, bare_rates);
  wrapped.state_derivative(1.0, y, wrapped_rates);
  EXPECT_EQ(bare_rates, wrapped_rates);
  EXPECT_GT(bare_rates.tail(6).norm(), 0.0);
}

/// A load (1, 2, 3) N at the body origin that counts its apply() calls, or throws.
class CountingLoad : public ForceElement {
 public:
  CountingLoad(int link, bool throws) : throws(throws), link_(link) {}
  const std::string& name() const override { return name_; }
  void apply(double, const Model& model, const Data& data, Eigen::Ref<const VectorX>,
             AppliedForces& forces) const override {
    ++applies;
    const Vector3 origin = (data.X_world_link[link_] * model.links[link_].X_link_body).translation();
    forces.add_force_at_point(link_, origin, Vector3(1.0, 2.0, 3.0));
    if (throws) throw std::runtime_error("counting load: asked to fail");
  }
  mutable int applies = 0;
  bool throws;

 private:
  std::string name_ = "counting";
  int link_;
};

TEST(RecordedLoad, ReadsBackTheLoadOfItsEvaluationWithoutApplyingAgain) {
  const RestoredHull hull;
  MultibodySystem system(hull.model);
  auto counting = std::make_unique<CountingLoad>(hull.link, false);
  const CountingLoad& load = *counting;
  auto wrapper = std::make_unique<RecordedLoad>(std::move(counting), *hull.model, hull.link, nullptr);
  const RecordedLoad& recorded = *wrapper;
  system.add_force_element(std::move(wrapper));
  const VectorX y = system.initial_state(hull.configuration(0.4, -0.3, -0.5, 0.05), VectorX::Zero(6));
  VectorX ydot(system.size());
  std::vector<double> values(6);
  system.state_derivative(1.0, y, ydot);
  ASSERT_EQ(load.applies, 1);
  recorded.outputs(1.0, system.model(), system.data(), VectorX(), values);
  EXPECT_EQ(load.applies, 1);  // read back
  // At the body origin: the force, and no moment about it.
  const std::vector<double> expected = {1.0, 2.0, 3.0, 0.0, 0.0, 0.0};
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(values[i], expected[i], 1e-12) << "channel " << i;
  // The same stages at another time (a copy of the Data, its time moved): applied again.
  Data later = system.data();
  later.stages.time = 1.5;
  recorded.outputs(1.5, system.model(), later, VectorX(), values);
  EXPECT_EQ(load.applies, 2);
}

TEST(RecordedLoad, AFailingElementLeavesTheLoadsBeforeItStanding) {
  // ... and keeps nothing of the failed point: outputs() there applies the element again.
  const RestoredHull hull;
  auto counting = std::make_unique<CountingLoad>(hull.link, true);
  CountingLoad& load = *counting;
  const RecordedLoad recorded(std::move(counting), *hull.model, hull.link, nullptr);
  Data data(*hull.model);
  const VectorX q = hull.configuration(0.0, 0.0, 0.0, 0.0);
  update_positions(*hull.model, data, q);
  update_velocities(*hull.model, data, q, VectorX::Zero(6));
  data.stages.time = 0.0;
  AppliedForces forces(*hull.model);
  const Force before(Vector3(4.0, 5.0, 6.0), Vector3(7.0, 8.0, 9.0));
  forces.external_force_world[hull.link] = before;
  EXPECT_THROW(recorded.apply(0.0, *hull.model, data, VectorX(), forces), std::runtime_error);
  EXPECT_EQ(forces.external_force_world[hull.link].vector(), before.vector());
  ASSERT_EQ(load.applies, 1);
  load.throws = false;
  std::vector<double> values(6);
  recorded.outputs(0.0, *hull.model, data, VectorX(), values);
  EXPECT_EQ(load.applies, 2);
  EXPECT_EQ(values[2], 3.0);
}

}  // namespace
}  // namespace heavesim
