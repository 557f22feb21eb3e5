// ForceElement::dependencies() lets the implicit forms skip the finite-difference
// columns of what no element reads: a declaration that says "does not depend on v" for
// an element that does would silently drop Newton-matrix columns. Each element here is
// evaluated at a state and again with only the quantity it says it ignores changed (the
// time, the speeds, the pose, its own states): its loads and state rates must not move
// at all. The perturbations are large (order one in every component), so any real
// dependence shows far above round-off; the comparison is exact.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>

#include "hydro/elements/linear_body_loads.hpp"
#include "hydro/elements/radiation_convolution.hpp"
#include "hydro/elements/wave_excitation.hpp"
#include "hydro/waves/wave_spectrum.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/elements/ground_contact.hpp"
#include "kernel/elements/joint_torque.hpp"
#include "kernel/elements/point_force.hpp"
#include "kernel/elements/spring_damper.hpp"
#include "samples/floating_bodies.hpp"

namespace heavesim {
namespace {

struct Evaluation {
  AlignedVector<Force> loads;
  VectorX joint_force, state_rate;
};

class ElementDependencyTest : public ::testing::Test {
 protected:
  ElementDependencyTest()
      : model_(samples::free_floating_body("hull", Inertia(3.0, Vector3(0.1, -0.2, 0.05),
                                                           Matrix3(Vector3(0.4, 0.5, 0.6).asDiagonal())))),
        data_(*model_) {
    q_.resize(7);
    q_ << 0.3, -0.2, -0.15, std::cos(0.2), std::sin(0.2) * 0.6, 0.0, std::sin(0.2) * 0.8;
    v_.resize(6);
    v_ << 0.3, -0.1, 0.2, 0.5, -0.4, 0.25;
  }

  Evaluation evaluate(const ForceElement& element, double t, const VectorX& q, const VectorX& v,
                      const VectorX& z) {
    update_positions(*model_, data_, q);
    update_velocities(*model_, data_, q, v);
    AppliedForces forces(*model_);
    element.apply(t, *model_, data_, z, forces);
    Evaluation result{forces.external_force_world, forces.joint_force, VectorX::Zero(z.size())};
    element.state_derivative(t, *model_, data_, z, result.state_rate);
    return result;
  }

  static void expect_same(const Evaluation& a, const Evaluation& b, const std::string& what) {
    for (std::size_t i = 0; i < a.loads.size(); ++i) {
      EXPECT_EQ(a.loads[i].angular(), b.loads[i].angular()) << what << ", link " << i;
      EXPECT_EQ(a.loads[i].linear(), b.loads[i].linear()) << what << ", link " << i;
    }
    EXPECT_EQ(a.joint_force, b.joint_force) << what;
    EXPECT_EQ(a.state_rate, b.state_rate) << what;
  }

  /// The element loads the body at the base state (so the checks are not vacuous), and
  /// its loads do not move when anything it says it ignores moves.
  void check(const ForceElement& element) {
    const ElementDependencies declared = element.dependencies();
    VectorX z = VectorX::Zero(element.state_size());
    element.initial_state(z);
    const Evaluation base = evaluate(element, 1.0, q_, v_, z);
    EXPECT_GT(base.loads[1].linear().norm() + base.loads[1].angular().norm(), 1.0) << element.name();
    if (!declared.time) expect_same(base, evaluate(element, 7.5, q_, v_, z), element.name() + ": time");
    if (!declared.velocity) {
      VectorX v = v_;
      v << -0.7, 0.9, 0.4, -1.1, 0.8, -0.6;
      expect_same(base, evaluate(element, 1.0, q_, v, z), element.name() + ": speeds");
    }
    if (!declared.configuration) {
      VectorX q = q_;
      q << -0.4, 0.5, 0.35, std::cos(0.6), 0.0, std::sin(0.6), 0.0;
      expect_same(base, evaluate(element, 1.0, q, v_, z), element.name() + ": pose");
    }
    if (!declared.element_states && z.size() > 0)
      expect_same(base, evaluate(element, 1.0, q_, v_, z.array() + 1.0), element.name() + ": own states");
    if (!declared.history) {
      // After calls at later and earlier times, other poses and speeds, the same loads at the
      // base state: what lets the recorder evaluate its samples on a copy of the system.
      VectorX q = q_, v = v_;
      q << 0.9, 0.1, -0.6, std::cos(0.9), 0.0, 0.0, std::sin(0.9);
      v << 1.2, -0.8, 0.1, -0.3, 0.6, 2.0;
      for (const double t : {40.0, 0.25, 40.5, 3.0}) evaluate(element, t, q, v, z.array() + 0.5);
      expect_same(base, evaluate(element, 1.0, q_, v_, z), element.name() + ": history");
    }
  }

  std::shared_ptr<const Model> model_;
  Data data_;
  VectorX q_, v_;
};

TEST_F(ElementDependencyTest, KernelElementsReadOnlyWhatTheyDeclare) {
  check(SpringDamper("spring", BodyPoint{0, Vector3(1.0, 0.5, 2.0)}, BodyPoint{1, Vector3(0.2, 0.1, -0.3)},
                     SpringDamperParameters{100.0, 5.0, 0.5}));
  check(PointForce("hook", BodyPoint{1, Vector3(0.2, -0.1, 0.4)}, Vector3(10.0, -20.0, -300.0)));
  // The surface above the point, so that the contact carries load in both states.
  check(GroundContact("bit", BodyPoint{1, Vector3(0.0, 0.0, -0.1)}, GroundContactParameters{1e4, 50.0, 2.0}));
}

TEST_F(ElementDependencyTest, JointTorqueReadsOnlyWhatItDeclares) {
  // It loads a coordinate, not a link, so check()'s link-load test does not apply; the
  // same comparisons are made here by hand. A constant torque declares nothing at all.
  const JointTorque constant("motor", 2, [](double) { return 3.5; }, false);
  const VectorX no_states;
  const Evaluation base = evaluate(constant, 1.0, q_, v_, no_states);
  EXPECT_EQ(base.joint_force[2], 3.5);
  EXPECT_EQ(base.joint_force.cwiseAbs().sum(), 3.5);
  expect_same(base, evaluate(constant, 7.5, q_, v_, no_states), "constant torque: time");
  VectorX q = q_, v = v_;
  q << -0.4, 0.5, 0.35, std::cos(0.6), 0.0, std::sin(0.6), 0.0;
  v << -0.7, 0.9, 0.4, -1.1, 0.8, -0.6;
  expect_same(base, evaluate(constant, 1.0, q, v_, no_states), "constant torque: pose");
  expect_same(base, evaluate(constant, 1.0, q_, v, no_states), "constant torque: speeds");
  // A torque of t declares the time, and does move with it.
  const JointTorque ramp("ramp", 2, [](double t) { return 2.0 * t; }, true);
  EXPECT_TRUE(ramp.dependencies().time);
  EXPECT_FALSE(ramp.dependencies().configuration || ramp.dependencies().velocity);
  EXPECT_NE(evaluate(ramp, 1.0, q_, v_, no_states).joint_force[2], evaluate(ramp, 7.5, q_, v_, no_states).joint_force[2]);
  expect_same(evaluate(ramp, 1.0, q_, v_, no_states), evaluate(ramp, 1.0, q, v, no_states), "ramp torque: pose, speeds");
}

TEST_F(ElementDependencyTest, LinearHydroLoadsReadOnlyWhatTheyDeclare) {
  Matrix6 stiffness = Matrix6::Identity() * 1e3;
  stiffness(3, 5) = 40.0;  // an asymmetric coupling, as WAMIT's C46 after the gravity part is taken out
  Vector6 pretension;
  pretension << 1.0, -2.0, 30.0, 0.1, 0.2, 0.0;
  check(hydro::LinearRestoring("restoring", 1, stiffness, pretension, Transform::Identity()));
  Vector6 quadratic;
  quadratic << 1.0, 2.0, 3.0, 0.4, 0.5, 0.6;
  check(hydro::BodyDamping("damping", 1, Matrix6::Identity() * 20.0, quadratic));
}

TEST_F(ElementDependencyTest, WaveExcitationReadsOnlyWhatItDeclares) {
  // Its phasors live on a grid it moves with the time asked (mutable state): the history
  // check asks later, earlier and later again before the base time, so the grid restarts.
  hydro::ExcitationData excitation;
  excitation.angular_frequencies = {0.3, 0.6, 1.2};
  excitation.headings = {0.0, M_PI / 2};
  excitation.force.assign(2, std::vector<hydro::ComplexVector6>(3, hydro::ComplexVector6::Constant({1e5, 2e4})));
  hydro::IrregularSeaSettings sea;
  sea.num_components = 50;
  sea.heading = 0.3;
  check(hydro::WaveExcitation("waves", 1, excitation, hydro::irregular_sea(hydro::PiersonMoskowitz{2.0, 8.0}, sea)));
}

TEST_F(ElementDependencyTest, RadiationConvolutionDeclaresItsHistory) {
  // The convolution's load is the integral over the velocities it stored at earlier calls:
  // the same state after other calls gives another load, and it says so.
  const hydro::RadiationConvolution convolution(
      "convolution", 1, hydro::RetardationKernel{0.1, std::vector<Matrix6>(50, Matrix6::Identity() * 1e3)});
  EXPECT_TRUE(convolution.dependencies().history);
  const VectorX no_states;
  const Evaluation first = evaluate(convolution, 1.0, q_, v_, no_states);
  VectorX v = v_;
  v << 1.2, -0.8, 0.1, -0.3, 0.6, 2.0;
  for (const double t : {1.1, 1.2, 1.3}) evaluate(convolution, t, q_, v, no_states);
  const Evaluation later = evaluate(convolution, 1.35, q_, v_, no_states);
  const Evaluation fresh = evaluate(hydro::RadiationConvolution("fresh", 1, hydro::RetardationKernel{
                                        0.1, std::vector<Matrix6>(50, Matrix6::Identity() * 1e3)}),
                                    1.35, q_, v_, no_states);
  EXPECT_GT(first.loads[1].linear().norm(), 0.0);
  EXPECT_GT((later.loads[1].linear() - fresh.loads[1].linear()).norm(), 1.0);
}

}  // namespace
}  // namespace heavesim
