// Constraint equations against finite differences of Phi itself: J = dPhi/dq along
// every tangent direction, gamma = -(d^2 Phi/dt^2 at qdd = 0), and the loads J^T lambda.
#include <gtest/gtest.h>

#include <random>

#include "kernel/algorithms/configuration.hpp"
#include "kernel/algorithms/inverse_dynamics.hpp"
#include "kernel/algorithms/constraint_equations.hpp"
#include "kernel/algorithms/projection.hpp"
#include "kernel/model/model_builder.hpp"
#include "samples/loop_mechanisms.hpp"
#include "samples/random_models.hpp"

namespace heavesim {
namespace {

class Constraints : public ::testing::Test {
 protected:
  Constraints() {
    samples::RandomTreeOptions options;
    options.bodies = 10;
    options.constraints = true;
    model = std::make_unique<Model>(samples::random_tree(random, options));
    data = std::make_unique<Data>(*model);
  }
  VectorX residual_at(const VectorX& q, double t = time) {
    VectorX phi(model->num_constraint_rows);
    update_positions(*model, *data, q);
    constraint_residual(*model, *data, q, t, phi);
    return phi;
  }
  static constexpr double time = 0.7;  // s; the driver makes Phi depend on t
  std::mt19937_64 random{21};
  std::unique_ptr<Model> model;
  std::unique_ptr<Data> data;
};

TEST_F(Constraints, EveryKindContributesItsRows) {
  // fixed 6 + revolute 5 + prismatic 5 + cylindrical 4 + universal 4 + spherical 3 + distance 1 + coupler 1
  // + joint, absolute, distance and angle drivers 1 each
  EXPECT_EQ(model->num_constraint_rows, 33);
}

TEST_F(Constraints, JacobianIsTheDerivativeOfTheResidual) {
  for (int trial = 0; trial < 5; ++trial) {
    const samples::RandomState state = samples::random_state(*model, random);
    update_positions(*model, *data, state.q);
    MatrixX J(model->num_constraint_rows, model->nv);
    constraint_jacobian(*model, *data, time, J);
    const double h = 1e-6;
    VectorX q_plus(model->nq), q_minus(model->nq);
    MatrixX finite(model->num_constraint_rows, model->nv);
    for (int j = 0; j < model->nv; ++j) {
      integrate_configuration(*model, state.q, VectorX::Unit(model->nv, j), h, q_plus);
      integrate_configuration(*model, state.q, VectorX::Unit(model->nv, j), -h, q_minus);
      finite.col(j) = (residual_at(q_plus) - residual_at(q_minus)) / (2 * h);
    }
    EXPECT_LT((J - finite).norm() / J.norm(), 1e-8);
  }
}

TEST_F(Constraints, BiasIsMinusTheSecondDerivativeAtZeroAcceleration) {
  // Along q(t) = q "+" v t (constant speeds: qdd = 0) Phi'' = dJ/dt v = -gamma.
  for (int trial = 0; trial < 5; ++trial) {
    const samples::RandomState state = samples::random_state(*model, random);
    update_positions(*model, *data, state.q);
    update_velocities(*model, *data, state.q, state.v);
    VectorX gamma(model->num_constraint_rows);
    constraint_bias(*model, *data, time, gamma);
    const double h = 1e-4;
    VectorX q_plus(model->nq), q_minus(model->nq);
    integrate_configuration(*model, state.q, state.v, h, q_plus);
    integrate_configuration(*model, state.q, state.v, -h, q_minus);
    const VectorX second = (residual_at(q_plus, time + h) - 2.0 * residual_at(state.q, time) +
                            residual_at(q_minus, time - h)) /
                           (h * h);
    EXPECT_LT((gamma + second).norm() / gamma.norm(), 1e-5);
  }
}

TEST_F(Constraints, VelocityTargetIsMinusTheTimeDerivative) {
  // d/dt Phi(q(t), t) = J v - nu along q(t) = q "+" v t.
  for (int trial = 0; trial < 5; ++trial) {
    const samples::RandomState state = samples::random_state(*model, random);
    update_positions(*model, *data, state.q);
    MatrixX J(model->num_constraint_rows, model->nv);
    constraint_jacobian(*model, *data, time, J);
    VectorX nu(model->num_constraint_rows);
    constraint_velocity_target(*model, *data, time, nu);
    EXPECT_GT(nu.cwiseAbs().maxCoeff(), 0.1);  // the driver moves
    const double h = 1e-6;
    VectorX q_plus(model->nq), q_minus(model->nq);
    integrate_configuration(*model, state.q, state.v, h, q_plus);
    integrate_configuration(*model, state.q, state.v, -h, q_minus);
    const VectorX rate = (residual_at(q_plus, time + h) - residual_at(q_minus, time - h)) / (2 * h);
    const VectorX expected = J * state.v - nu;
    EXPECT_LT((rate - expected).norm() / expected.norm(), 1e-8);
  }
}

TEST_F(Constraints, LoadsAreJacobianTransposeTimesMultipliers) {
  const samples::RandomState state = samples::random_state(*model, random);
  update_positions(*model, *data, state.q);
  MatrixX J(model->num_constraint_rows, model->nv);
  constraint_jacobian(*model, *data, time, J);
  VectorX lambda(model->num_constraint_rows);
  for (int r = 0; r < lambda.size(); ++r) lambda[r] = std::uniform_real_distribution<double>(-5, 5)(random);
  AlignedVector<Force> loads(model->num_links(), Force::Zero());
  VectorX tau = VectorX::Zero(model->nv);
  add_constraint_loads(*model, *data, time, lambda, loads, tau);
  // Generalized force of the link loads: -(ID with them - ID without), at v = qdd = 0.
  const VectorX zero = VectorX::Zero(model->nv);
  const VectorX with_loads = rnea(*model, *data, state.q, zero, zero, loads);
  const VectorX without = rnea(*model, *data, state.q, zero, zero);
  const VectorX generalized = tau - (with_loads - without);
  EXPECT_LT((generalized - J.transpose() * lambda).norm() / generalized.norm(), 1e-12);
}

TEST(ConstraintRank, RedundantRowsOfAnOverconstrainedLoopAreNamed) {
  // Two parallel prismatic rods on the ground tied to one block by fixed loop joints:
  // the block is on rod a (fixed); the fixed joint to rod b repeats all but one of
  // rod a's constraints, so 5 of its 6 rows are redundant.
  const Model model = samples::overconstrained_rails();
  Data data(model);
  update_positions(model, data, model.neutral_configuration());
  const ConstraintRank rank = analyse_constraint_rank(model, data, 0.0);
  EXPECT_EQ(rank.rows, 6);
  EXPECT_EQ(rank.rank, 1);
  EXPECT_EQ(rank.redundant_rows.size(), 5u);
  EXPECT_NE(describe_constraint_row(model, 2).find("loop joint 'weld_b': translation along z"), std::string::npos);
}

TEST(ConstraintRank, RedundantRowsOfAPlanarFourBarAreNamedInTheUsersJointFrame) {
  // A four-bar in the world xz plane, every joint revolute about the user's y axis, the
  // loop closed by a revolute loop joint: of its 5 rows the 3 that block out-of-plane
  // motion (translation along y, rotations about x and z) are redundant, since planar
  // joints cannot violate them (their Jacobian rows are zero). The kernel writes the
  // rows on a frame turned so that the axis is z; they must be named in the user's.
  ModelBuilder builder;
  for (const char* body : {"crank", "coupler", "rocker"})
    builder.add_body({body, Inertia(1.0, Vector3::Zero(), Matrix3::Identity() * 0.1), std::nullopt});
  auto revolute = [](const char* name, const char* parent, const char* child, const Vector3& at) {
    JointDefinition joint;
    joint.name = name;
    joint.kind = JointKind::revolute;
    joint.axis = Vector3::UnitY();
    joint.parent = parent;
    joint.child = child;
    joint.X_parent_joint = Transform::from_translation(at);
    return joint;
  };
  builder.add_joint(revolute("pivot_a", "ground", "crank", Vector3::Zero()));
  builder.add_joint(revolute("pin", "crank", "coupler", Vector3(0, 0, 1)));
  builder.add_joint(revolute("pivot_b", "ground", "rocker", Vector3(2, 0, 0)));
  LoopJointDefinition closure;  // coupler (2, 0, 0.5) meets rocker (0, 0, 1.5) at world (2, 0, 1.5)
  closure.name = "closure";
  closure.kind = JointKind::revolute;
  closure.axis = Vector3::UnitY();
  closure.parent = "coupler";
  closure.child = "rocker";
  closure.X_parent_joint = Transform::from_translation(Vector3(2, 0, 0.5));
  closure.X_child_joint = Transform::from_translation(Vector3(0, 0, 1.5));
  builder.add_loop_joint(closure);
  const Model model = builder.build();
  Data data(model);
  update_positions(model, data, model.neutral_configuration());
  const ConstraintRank rank = analyse_constraint_rank(model, data, 0.0);
  EXPECT_EQ(rank.rows, 5);
  EXPECT_EQ(rank.rank, 2);
  std::vector<std::string> redundant;
  for (int row : rank.redundant_rows) redundant.push_back(describe_constraint_row(model, row));
  EXPECT_EQ(redundant, (std::vector<std::string>{"loop joint 'closure': translation along y",
                                                 "loop joint 'closure': rotation about x",
                                                 "loop joint 'closure': rotation about z"}));
  // And the two rows that close the loop in its plane.
  EXPECT_EQ(describe_constraint_row(model, 0), "loop joint 'closure': translation along x");
  EXPECT_EQ(describe_constraint_row(model, 1), "loop joint 'closure': translation along z");
}

}  // namespace
}  // namespace heavesim
