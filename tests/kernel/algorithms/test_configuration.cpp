// Configuration maps on random trees of every joint type: difference() inverts
// integrate(); integrating a constant velocity is a one-parameter group
// (q + v (s + t) = (q + v s) + v t on the manifold); and qdot = N(q) v is the time
// derivative of integrate() along v.
#include <gtest/gtest.h>

#include <random>

#include "kernel/algorithms/configuration.hpp"
#include "samples/random_models.hpp"

namespace heavesim {
namespace {

class Configuration : public ::testing::Test {
 protected:
  Configuration() {
    samples::RandomTreeOptions options;
    options.bodies = 21;  // every joint type three times
    model = std::make_unique<Model>(samples::random_tree(random, options));
  }
  std::mt19937_64 random{71};
  std::unique_ptr<Model> model;
};

TEST_F(Configuration, DifferenceInvertsIntegrate) {
  for (int trial = 0; trial < 10; ++trial) {
    const samples::RandomState state = samples::random_state(*model, random);
    // Half the random velocity keeps every rotation below pi (|w| <= sqrt(3) rad),
    // where the logarithm is unique.
    const VectorX displacement = 0.5 * state.v;
    VectorX q1(model->nq), recovered(model->nv);
    integrate_configuration(*model, state.q, displacement, 1.0, q1);
    configuration_difference(*model, state.q, q1, recovered);
    // Entries of order 1 through exp and log: a few eps per operation, bound 1e-12.
    EXPECT_LT((recovered - displacement).norm(), 1e-12) << "trial " << trial;
  }
}

TEST_F(Configuration, ConstantVelocityIntegrationIsAOneParameterGroup) {
  for (int trial = 0; trial < 10; ++trial) {
    const samples::RandomState state = samples::random_state(*model, random);
    const double first = 0.3, second = 0.45;
    VectorX in_one_step(model->nq), halfway(model->nq), in_two_steps(model->nq);
    integrate_configuration(*model, state.q, state.v, first + second, in_one_step);
    integrate_configuration(*model, state.q, state.v, first, halfway);
    integrate_configuration(*model, halfway, state.v, second, in_two_steps);
    // exp(v (s + t)) = exp(v s) exp(v t) on SO(3) and SE(3); coordinates of order 1,
    // a few dozen operations each: bound 1e-13.
    EXPECT_LT((in_one_step - in_two_steps).norm(), 1e-13) << "trial " << trial;
  }
}

TEST_F(Configuration, DerivativeIsTheRateOfIntegrate) {
  for (int trial = 0; trial < 10; ++trial) {
    const samples::RandomState state = samples::random_state(*model, random);
    VectorX qdot(model->nq), q_plus(model->nq), q_minus(model->nq);
    configuration_derivative(*model, state.q, state.v, qdot);
    const double h = 1e-6;
    integrate_configuration(*model, state.q, state.v, h, q_plus);
    integrate_configuration(*model, state.q, state.v, -h, q_minus);
    // Central difference: truncation ~h^2 |q'''| ~ 1e-12, round-off ~eps / h ~ 1e-10.
    EXPECT_LT((qdot - (q_plus - q_minus) / (2 * h)).norm(), 1e-8) << "trial " << trial;
  }
}

}  // namespace
}  // namespace heavesim
