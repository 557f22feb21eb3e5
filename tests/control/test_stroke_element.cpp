// What every compensator shares (control/stroke/stroke_element.hpp): apply(),
// state_derivative() and outputs() are one evaluation seen three ways, evaluated once per
// point (kernel/elements/evaluation_key.hpp) and again whenever the time, the element
// states or the stages change. A counting element with a closed-form state pins both.
#include <gtest/gtest.h>

#include "control/stroke/stroke_element.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "samples/oscillators.hpp"

namespace heavesim {
namespace {

struct CountedState {
  double force = 0.0;  // N: 10 z + t + q
  double time = 0.0;   // s
};
struct NoParameters {};

class CountingStroke : public StrokeElement<CountedState, NoParameters> {
 public:
  explicit CountingStroke(StrokeAxis axis) : StrokeElement("counting", axis, {}) {
    table_.add("force", "N", "10 z + t + q", &CountedState::force);
    table_.add("time", "s", "t", &CountedState::time);
  }
  int state_size() const override { return 1; }
  CountedState evaluate(double t, const Model&, const Data& data, Eigen::Ref<const VectorX> z,
                        double* zdot) const override {
    ++evaluations;
    if (zdot) zdot[0] = t - z[0];
    return {10.0 * z[0] + t + data.q[0], t};
  }
  mutable int evaluations = 0;
};

TEST(StrokeElement, OneEvaluationPerPointAndANewOneAtEveryChange) {
  const auto model = samples::vertical_slider(100.0);
  Data data(*model);
  const CountingStroke element(StrokeAxis::on_joint(*model, 1, 0.0));
  auto place = [&](double q) {
    update_positions(*model, data, VectorX::Constant(1, q));
    update_velocities(*model, data, VectorX::Constant(1, q), VectorX::Zero(1));
  };
  // Apply, rates and outputs at (t, q, z), each checked against the closed form.
  auto expect_point = [&](double t, double q, double z, int evaluations) {
    const VectorX states = VectorX::Constant(1, z);
    AppliedForces forces(*model);
    VectorX rate(1);
    std::vector<double> values(2);
    element.apply(t, *model, data, states, forces);
    element.state_derivative(t, *model, data, states, rate);
    element.outputs(t, *model, data, states, values);
    EXPECT_EQ(forces.joint_force[0], 10.0 * z + t + q);  // on the joint's coordinate, along the stroke
    EXPECT_EQ(rate[0], t - z);
    EXPECT_EQ(values, (std::vector<double>{10.0 * z + t + q, t}));
    EXPECT_EQ(element.evaluations, evaluations) << "t = " << t << ", q = " << q << ", z = " << z;
  };
  place(0.5);
  expect_point(1.0, 0.5, 2.0, 1);  // three reads, one evaluation
  expect_point(1.0, 0.5, 2.0, 1);  // the same point again
  expect_point(1.5, 0.5, 2.0, 2);  // another time
  expect_point(1.5, 0.5, 3.0, 3);  // other element states
  place(0.5);                      // the same q, but a new evaluation of the stages
  expect_point(1.5, 0.5, 3.0, 4);
  place(-0.25);
  expect_point(1.5, -0.25, 3.0, 5);
}

}  // namespace
}  // namespace heavesim
