// Analytical derivatives of inverse dynamics against central finite differences of
// RNEA, on random trees with every joint type, added inertia and external forces.
#include <gtest/gtest.h>

#include <random>

#include "kernel/algorithms/configuration.hpp"
#include "kernel/algorithms/inverse_dynamics_derivatives.hpp"
#include "samples/random_models.hpp"

namespace heavesim {
namespace {

TEST(InverseDynamicsDerivatives, MatchFiniteDifferencesOfRnea) {
  std::mt19937_64 random(11);
  for (int trial = 0; trial < 10; ++trial) {
    const samples::RandomTreeAndState drawn = samples::random_tree_and_state(random, 10, trial % 2 == 1);
    const Model& model = drawn.model;
    const samples::RandomState& state = drawn.state;
    Data data(model);
    const VectorX qdd = state.tau;  // any acceleration will do

    inverse_dynamics_derivatives(model, data, state.q, state.v, qdd, state.external_forces);
    const MatrixX dtau_dq = data.dtau_dq, dtau_dv = data.dtau_dv;

    // Central differences along each tangent direction, step 1e-6 (error ~1e-10).
    const double h = 1e-6;
    MatrixX fd_q(model.nv, model.nv), fd_v(model.nv, model.nv);
    VectorX q_plus(model.nq), q_minus(model.nq);
    for (int j = 0; j < model.nv; ++j) {
      const VectorX e = VectorX::Unit(model.nv, j);
      integrate_configuration(model, state.q, e, h, q_plus);
      integrate_configuration(model, state.q, e, -h, q_minus);
      // rnea returns a reference into data: copy each result before the next call.
      const VectorX tau_q_plus = rnea(model, data, q_plus, state.v, qdd, state.external_forces);
      const VectorX tau_q_minus = rnea(model, data, q_minus, state.v, qdd, state.external_forces);
      const VectorX tau_v_plus = rnea(model, data, state.q, state.v + h * e, qdd, state.external_forces);
      const VectorX tau_v_minus = rnea(model, data, state.q, state.v - h * e, qdd, state.external_forces);
      fd_q.col(j) = (tau_q_plus - tau_q_minus) / (2 * h);
      fd_v.col(j) = (tau_v_plus - tau_v_minus) / (2 * h);
    }
    EXPECT_LT((dtau_dq - fd_q).norm() / fd_q.norm(), 1e-8) << "trial " << trial;
    EXPECT_LT((dtau_dv - fd_v).norm() / fd_v.norm(), 1e-8) << "trial " << trial;
  }
}

TEST(InverseDynamicsDerivatives, VelocityDerivativeOfAQuadraticFormIsExact) {
  // tau is quadratic in v, so dtau/dv(v) = (tau(v + e) - tau(v - e)) / 2 for any e:
  // a check that needs no small step.
  std::mt19937_64 random(12);
  const Model model = samples::random_tree(random, samples::RandomTreeOptions{});
  Data data(model);
  const samples::RandomState state = samples::random_state(model, random);
  inverse_dynamics_derivatives(model, data, state.q, state.v, state.tau);
  const MatrixX analytic = data.dtau_dv;
  for (int j = 0; j < model.nv; ++j) {
    const VectorX e = VectorX::Unit(model.nv, j);
    const VectorX tau_plus = rnea(model, data, state.q, state.v + e, state.tau);
    const VectorX tau_minus = rnea(model, data, state.q, state.v - e, state.tau);
    const VectorX exact = (tau_plus - tau_minus) / 2.0;
    EXPECT_LT((analytic.col(j) - exact).norm(), 1e-10 * (1.0 + exact.norm())) << "column " << j;
  }
}

}  // namespace
}  // namespace heavesim
