// Automatic differentiation as the oracle of every analytic Jacobian and gamma term.
//
// The test writes its own forward kinematics, templated on the scalar (the placement of
// every link from q, joint by joint, from the joint conventions of kernel/joints/*.hpp:
// revolute Rz(q), prismatic z q, cylindrical Rz(q0) and z q1, universal Rx(q0) Ry(q1),
// spherical and free by the exponential of a body-frame increment), and the constraint
// functions Phi(q, t) of every kind from their definitions (constraint.hpp). Forward-mode
// AD (Eigen's AutoDiffScalar) of these gives
//   J_AD     = dPhi(q0 (+) eps, t) / d eps at eps = 0      (eps in velocity coordinates)
//   nu_AD    = -dPhi/dt                                     (q fixed)
//   gamma_AD = -d2/dt2 Phi(q0 (+) v t, t) at t = 0          (nested AutoDiffScalar)
// where q0 (+) v t is the motion at constant speeds v in each joint's own velocity
// coordinates (qdd = 0), so that Phi'' = -gamma there. The same AD of the links'
// placements gives their spatial velocities per unit speed (the motion subspaces) and
// their spatial accelerations at qdd = 0 (the sums of the bias accelerations c_J + v x v_J).
//
// Tolerance: AD evaluates the same expressions as the analytic code in another order, so
// both are exact up to round-off: a few ulp per operation over the chain of ~10 links
// (each placement a product of 3x3 matrices of entries <= 1 and lever arms <= ~5 m),
// i.e. ~1e-14 relative to the row's scale (the largest entry of the row, or of the
// compared vector); 1e-12 leaves a factor 100 for the accumulation.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <set>

#include <unsupported/Eigen/AutoDiff>

#include "app/case/coordinate_expression.hpp"
#include "kernel/algorithms/constraint_equations.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/algorithms/projection.hpp"
#include "kernel/model/model_builder.hpp"
#include "samples/random_models.hpp"

namespace heavesim {
namespace {

// First derivatives with respect to all nv increments at once.
using Gradient = Eigen::AutoDiffScalar<Eigen::VectorXd>;
// Second derivatives in one variable (time): a derivative of a derivative.
using FirstOrder = Eigen::AutoDiffScalar<Eigen::Matrix<double, 1, 1>>;
using SecondOrder = Eigen::AutoDiffScalar<Eigen::Matrix<FirstOrder, 1, 1>>;

template <class S>
using V3 = Eigen::Matrix<S, 3, 1>;
template <class S>
using M3 = Eigen::Matrix<S, 3, 3>;
template <class S>
using VX = Eigen::Matrix<S, Eigen::Dynamic, 1>;

template <class S>
S constant(double value) {
  return S(value);
}
template <>
SecondOrder constant<SecondOrder>(double value) {
  return SecondOrder(FirstOrder(value));
}

template <class S>
double value_of(const S& x) {
  return x.value();
}
template <>
double value_of<SecondOrder>(const SecondOrder& x) {
  return x.value().value();
}

/// A placement: x_world = R x_local + p.
template <class S>
struct Pose {
  M3<S> R;
  V3<S> p;
  Pose operator*(const Pose& other) const { return {R * other.R, R * other.p + p}; }
};

template <class S>
Pose<S> constant_pose(const Transform& X) {
  Pose<S> pose;
  for (int r = 0; r < 3; ++r) {
    pose.p[r] = constant<S>(X.translation()[r]);
    for (int c = 0; c < 3; ++c) pose.R(r, c) = constant<S>(X.rotation()(r, c));
  }
  return pose;
}

template <class S>
M3<S> skew_of(const V3<S>& w) {
  M3<S> K;
  const S zero = constant<S>(0.0), minus_x = -w.x(), minus_y = -w.y(), minus_z = -w.z();
  K << zero, minus_z, w.y(), w.z(), zero, minus_x, minus_y, w.x(), zero;
  return K;
}

/// exp([phi]x) (Rodrigues) and the left Jacobian V(phi) of SO(3), written on
/// theta^2 = phi . phi so that they are smooth at phi = 0, where AD evaluates them: their
/// Taylor series there (the terms kept are exact to the second order AD asks for).
template <class S>
M3<S> rotation_exponential(const V3<S>& phi) {
  const M3<S> K = skew_of(phi);
  const S theta2 = phi.dot(phi);
  const M3<S> I = M3<S>::Identity();
  if (value_of(theta2) < 1e-12) {
    const S b = constant<S>(0.5) - theta2 / constant<S>(24.0);
    return I + K + K * K * b;
  }
  using std::cos;
  using std::sin;
  using std::sqrt;
  const S theta = sqrt(theta2);
  const S a = sin(theta) / theta, b = (constant<S>(1.0) - cos(theta)) / theta2;
  return I + K * a + K * K * b;
}
template <class S>
M3<S> left_jacobian_of(const V3<S>& phi) {
  const M3<S> K = skew_of(phi);
  const S theta2 = phi.dot(phi);
  const M3<S> I = M3<S>::Identity();
  if (value_of(theta2) < 1e-12) return I + K * constant<S>(0.5) + K * K * constant<S>(1.0 / 6.0);
  using std::cos;
  using std::sin;
  using std::sqrt;
  const S theta = sqrt(theta2);
  const S a = (constant<S>(1.0) - cos(theta)) / theta2, b = (theta - sin(theta)) / (theta2 * theta);
  return I + K * a + K * K * b;
}

template <class S>
M3<S> rotation_about(int axis, const S& angle) {
  using std::cos;
  using std::sin;
  const S c = cos(angle), s = sin(angle), minus_s = -s, one = constant<S>(1.0), zero = constant<S>(0.0);
  M3<S> R;
  if (axis == 0) R << one, zero, zero, zero, c, minus_s, zero, s, c;
  if (axis == 1) R << c, zero, s, zero, one, zero, minus_s, zero, c;
  if (axis == 2) R << c, minus_s, zero, s, c, zero, zero, zero, one;
  return R;
}

/// The joint's placement X_J(q0 (+) eps): the child-side frame in the parent-side frame.
template <class S>
Pose<S> joint_pose(const Joint& joint, const VectorX& q0, const VX<S>& eps) {
  const double* q = q0.data() + joint.q_index;
  // Every lambda returns S: AutoDiffScalar's expression types would keep references to
  // the temporaries they were built from.
  auto e = [&](int k) -> S { return eps[joint.v_index + k]; };
  auto plain = [&](int k) -> S { return constant<S>(q[k]) + e(k); };
  Pose<S> pose{M3<S>::Identity(), V3<S>::Constant(constant<S>(0.0))};
  if (std::holds_alternative<RevoluteJoint>(joint.type)) pose.R = rotation_about<S>(2, plain(0));
  if (std::holds_alternative<PrismaticJoint>(joint.type)) pose.p.z() = plain(0);
  if (std::holds_alternative<CylindricalJoint>(joint.type)) {
    pose.R = rotation_about<S>(2, plain(0));
    pose.p.z() = plain(1);
  }
  if (std::holds_alternative<UniversalJoint>(joint.type))
    pose.R = rotation_about<S>(0, plain(0)) * rotation_about<S>(1, plain(1));
  // Quaternion q = (w, x, y, z) of the child side in the parent side; the increment is
  // a rotation vector in the child side's axes (v is the child-side angular velocity).
  auto quaternion_rotation = [&](const double* w) -> M3<S> {
    return constant_pose<S>(Transform::from_rotation(
                                Eigen::Quaterniond(w[0], w[1], w[2], w[3]).normalized().toRotationMatrix()))
        .R;
  };
  if (std::holds_alternative<SphericalJoint>(joint.type)) {
    const V3<S> phi(e(0), e(1), e(2));
    pose.R = quaternion_rotation(q) * rotation_exponential(phi);
  }
  // Free: (angular, linear) velocity in child-side axes, a constant body twist:
  // R(t) = R0 exp(w t), p(t) = p0 + R0 V(w t) v t.
  if (std::holds_alternative<FreeJoint>(joint.type)) {
    const V3<S> phi(e(0), e(1), e(2)), displacement(e(3), e(4), e(5));
    const M3<S> R0 = quaternion_rotation(q + 3);
    pose.R = R0 * rotation_exponential(phi);
    pose.p = V3<S>(constant<S>(q[0]), constant<S>(q[1]), constant<S>(q[2])) + R0 * (left_jacobian_of(phi) * displacement);
  }
  return pose;
}

/// Every link's world placement (link 0 is the ground).
template <class S>
std::vector<Pose<S>> link_poses(const Model& model, const VectorX& q0, const VX<S>& eps) {
  std::vector<Pose<S>> poses(model.num_links());
  poses[0] = constant_pose<S>(Transform::Identity());
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    poses[i] = poses[joint.parent] * constant_pose<S>(joint.placement) * joint_pose(joint, q0, eps);
  }
  return poses;
}

/// f(t0 + tau) to second order from the driver's own f, f', f'' at t0 (exact for the
/// derivatives AD takes at tau = 0).
template <class S>
S prescribed(const DriverFunction& motion, double t0, const S& tau) {
  const DriverMotion f = motion(t0);
  return constant<S>(f.position) + tau * constant<S>(f.velocity) + tau * tau * constant<S>(0.5 * f.acceleration);
}

/// Phi(q0 (+) eps, t0 + tau) of every constraint, from the definitions in constraint.hpp.
template <class S>
VX<S> constraint_function(const Model& model, const VectorX& q0, const VX<S>& eps, double t0, const S& tau) {
  const std::vector<Pose<S>> poses = link_poses(model, q0, eps);
  VX<S> phi(model.num_constraint_rows);
  auto coordinate = [&](int joint, int k) -> S {
    return constant<S>(q0[model.joints[joint].q_index + k]) + eps[model.joints[joint].v_index + k];
  };
  for (const Constraint& constraint : model.constraints) {
    const int row0 = constraint.first_row;
    if (const auto* driver = std::get_if<DriverConstraint>(&constraint.kind)) {
      phi[row0] = coordinate(driver->joint, driver->coordinate) - prescribed(driver->motion, t0, tau);
      continue;
    }
    if (const auto* coupler = std::get_if<CouplerConstraint>(&constraint.kind)) {
      phi[row0] = coordinate(coupler->joint_a, 0) - constant<S>(coupler->ratio) * coordinate(coupler->joint_b, 0) -
                  constant<S>(coupler->offset);
      continue;
    }
    const Pose<S> A = poses[constraint.link_a] * constant_pose<S>(constraint.X_linkA_frame);
    const Pose<S> B = poses[constraint.link_b] * constant_pose<S>(constraint.X_linkB_frame);
    const V3<S> r = B.p - A.p;
    using std::atan2;
    using std::sqrt;
    if (const auto* absolute = std::get_if<AbsoluteDriverConstraint>(&constraint.kind)) {
      // direction . p_B - f(t): the direction is fixed in the world.
      phi[row0] = absolute->direction_world.cast<S>().dot(B.p) - prescribed(absolute->motion, t0, tau);
      continue;
    }
    if (const auto* distance = std::get_if<DistanceDriverConstraint>(&constraint.kind)) {
      const S length = sqrt(r.dot(r));
      phi[row0] = length - prescribed(distance->motion, t0, tau);
      continue;
    }
    if (const auto* angle = std::get_if<AngleDriverConstraint>(&constraint.kind)) {
      // theta = atan2(y_A . x_B, x_A . x_B); the residual is theta - f wrapped into
      // (-pi, pi]: a constant multiple of 2 pi, which AD does not see.
      const S sine = A.R.col(1).dot(B.R.col(0)), cosine = A.R.col(0).dot(B.R.col(0));
      const S theta = atan2(sine, cosine);
      const S difference = theta - prescribed(angle->motion, t0, tau);
      const double turns = std::round(value_of(difference) / (2 * std::numbers::pi));
      phi[row0] = difference - constant<S>(turns * 2 * std::numbers::pi);
      continue;
    }
    const double length = std::holds_alternative<DistanceConstraint>(constraint.kind)
                              ? std::get<DistanceConstraint>(constraint.kind).distance
                              : 0.0;
    for (std::size_t k = 0; k < constraint.rows.size(); ++k) {
      const ConstraintRow& row = constraint.rows[k];
      S& value = phi[row0 + static_cast<int>(k)];
      if (row.kind == ConstraintRowKind::along) value = A.R.col(row.axis_a).dot(r);
      if (row.kind == ConstraintRowKind::perpendicular) value = A.R.col(row.axis_a).dot(B.R.col(row.axis_b));
      if (row.kind == ConstraintRowKind::distance) value = constant<S>(0.5) * (r.dot(r) - constant<S>(length * length));
    }
  }
  return phi;
}

/// eps = unit seeds: derivative k is d/d eps_k.
VX<Gradient> seeded_increments(int nv) {
  VX<Gradient> eps(nv);
  for (int k = 0; k < nv; ++k) eps[k] = Gradient(0.0, nv, k);
  return eps;
}
Gradient gradient_constant(double value, int nv) { return Gradient(value, Eigen::VectorXd::Zero(nv)); }
/// The gradient of x over the nv increments (AD leaves it empty where x is a constant).
VectorX gradient_of(const Gradient& x, int nv) {
  return x.derivatives().size() == nv ? VectorX(x.derivatives()) : VectorX::Zero(nv);
}

/// tau as the variable of the second-order scalar: value 0, first derivative 1.
SecondOrder time_variable() {
  FirstOrder value(0.0, Eigen::Matrix<double, 1, 1>(1.0));
  Eigen::Matrix<FirstOrder, 1, 1> derivative;
  derivative[0] = FirstOrder(1.0, Eigen::Matrix<double, 1, 1>(0.0));
  return SecondOrder(value, derivative);
}
double first_derivative(const SecondOrder& x) { return x.derivatives()[0].value(); }
double second_derivative(const SecondOrder& x) { return x.derivatives()[0].derivatives()[0]; }

/// The largest entry of each row (at least 1e-300), for errors relative to the row's scale.
double relative_error(const Eigen::Ref<const VectorX>& analytic, const Eigen::Ref<const VectorX>& oracle) {
  const double scale = std::max({analytic.cwiseAbs().maxCoeff(), oracle.cwiseAbs().maxCoeff(), 1e-300});
  return (analytic - oracle).cwiseAbs().maxCoeff() / scale;
}

class ConstraintDerivativesAD : public ::testing::Test {
 protected:
  ConstraintDerivativesAD() {
    samples::RandomTreeOptions options;
    options.bodies = 14;  // every joint type twice
    options.constraints = true;
    model = std::make_unique<Model>(samples::random_tree(random, options));
    data = std::make_unique<Data>(*model);
  }
  std::mt19937_64 random{1414};
  std::unique_ptr<Model> model;
  std::unique_ptr<Data> data;
  static constexpr double time = 0.7;  // s
  static constexpr int trials = 8;
};

TEST_F(ConstraintDerivativesAD, ModelHasEveryConstraintKind) {
  std::set<std::string> kinds;
  for (const Constraint& constraint : model->constraints) kinds.insert(constraint.kind_name());
  EXPECT_EQ(kinds, (std::set<std::string>{"loop joint", "distance constraint", "coupler", "driver", "absolute driver",
                                          "distance driver", "angle driver"}));
  std::set<int> joint_kinds;
  for (int i = 1; i < model->num_links(); ++i) joint_kinds.insert(static_cast<int>(model->joints[i].type.index()));
  EXPECT_EQ(joint_kinds.size(), 7u);
}

TEST_F(ConstraintDerivativesAD, ResidualIsTheFunctionDifferentiated) {
  // The oracle differentiates its own Phi: first check it is the kernel's Phi.
  for (int trial = 0; trial < trials; ++trial) {
    const samples::RandomState state = samples::random_state(*model, random);
    update_positions(*model, *data, state.q);
    VectorX phi(model->num_constraint_rows);
    constraint_residual(*model, *data, state.q, time, phi);
    const VX<Gradient> oracle =
        constraint_function(*model, state.q, seeded_increments(model->nv), time, gradient_constant(0.0, model->nv));
    for (int row = 0; row < phi.size(); ++row)
      EXPECT_NEAR(phi[row], oracle[row].value(), 1e-12 * std::max(1.0, std::abs(phi[row]))) << row;
  }
}

TEST_F(ConstraintDerivativesAD, JacobianOfEveryKindIsTheDerivative) {
  for (int trial = 0; trial < trials; ++trial) {
    const samples::RandomState state = samples::random_state(*model, random);
    update_positions(*model, *data, state.q);
    MatrixX J(model->num_constraint_rows, model->nv);
    constraint_jacobian(*model, *data, time, J);
    const VX<Gradient> oracle =
        constraint_function(*model, state.q, seeded_increments(model->nv), time, gradient_constant(0.0, model->nv));
    for (int row = 0; row < J.rows(); ++row)
      EXPECT_LT(relative_error(J.row(row).transpose(), gradient_of(oracle[row], model->nv)), 1e-12)
          << describe_constraint_row(*model, row) << "\nanalytic " << J.row(row)
          << "\nAD       " << gradient_of(oracle[row], model->nv).transpose();
  }
}

TEST_F(ConstraintDerivativesAD, VelocityTargetIsMinusTheTimeDerivative) {
  const samples::RandomState state = samples::random_state(*model, random);
  update_positions(*model, *data, state.q);
  VectorX nu(model->num_constraint_rows);
  constraint_velocity_target(*model, *data, time, nu);
  const VX<SecondOrder> at_rest = VX<SecondOrder>::Constant(model->nv, constant<SecondOrder>(0.0));
  const VX<SecondOrder> oracle = constraint_function(*model, state.q, at_rest, time, time_variable());
  VectorX expected(nu.size());
  for (int row = 0; row < nu.size(); ++row) expected[row] = -first_derivative(oracle[row]);
  EXPECT_GT(expected.cwiseAbs().maxCoeff(), 0.1);  // the drivers move
  EXPECT_LT(relative_error(nu, expected), 1e-15);
}

TEST_F(ConstraintDerivativesAD, BiasOfEveryKindIsMinusTheSecondDerivativeAtConstantSpeeds) {
  for (int trial = 0; trial < trials; ++trial) {
    const samples::RandomState state = samples::random_state(*model, random);
    update_positions(*model, *data, state.q);
    update_velocities(*model, *data, state.q, state.v);
    VectorX gamma(model->num_constraint_rows);
    constraint_bias(*model, *data, time, gamma);
    // q(tau) = q0 (+) v tau and t = time + tau.
    const SecondOrder tau = time_variable();
    VX<SecondOrder> eps(model->nv);
    for (int k = 0; k < model->nv; ++k) eps[k] = tau * constant<SecondOrder>(state.v[k]);
    const VX<SecondOrder> oracle = constraint_function(*model, state.q, eps, time, tau);
    for (int row = 0; row < gamma.size(); ++row) {
      // Scale: |gamma| is ~|v|^2 times the row's lever arms; the terms it sums are up to ~10x larger.
      const double expected = -second_derivative(oracle[row]);
      EXPECT_NEAR(gamma[row], expected, 1e-12 * std::max(10.0, 10.0 * std::abs(expected))) << describe_constraint_row(*model, row);
    }
  }
}

TEST_F(ConstraintDerivativesAD, MotionSubspacesAndBiasAccelerationsOfEveryJointType) {
  // The spatial velocity of link i about the world origin is (w, pdot - w x p) with
  // [w]x = Rdot R^T; per unit v_k it is column k of the world motion subspace (the joint's
  // own and its ancestors'); at constant speeds its time derivative,
  // (wdot, pddot - wdot x p - w x pdot) with [wdot]x = Rddot R^T + Rdot Rdot^T, is the
  // sum of the bias accelerations c_j along the path to the ground.
  auto vee = [](const Matrix3& K) -> Vector3 { return Vector3(K(2, 1) - K(1, 2), K(0, 2) - K(2, 0), K(1, 0) - K(0, 1)) / 2; };
  for (int trial = 0; trial < trials; ++trial) {
    const samples::RandomState state = samples::random_state(*model, random);
    update_positions(*model, *data, state.q);
    update_velocities(*model, *data, state.q, state.v);
    const int nv = model->nv;
    const std::vector<Pose<Gradient>> gradient = link_poses(*model, state.q, seeded_increments(nv));
    const SecondOrder tau = time_variable();
    VX<SecondOrder> eps(nv);
    for (int k = 0; k < nv; ++k) eps[k] = tau * constant<SecondOrder>(state.v[k]);
    const std::vector<Pose<SecondOrder>> path = link_poses(*model, state.q, eps);
    for (int i = 1; i < model->num_links(); ++i) {
      SCOPED_TRACE(model->joints[i].name + " (" + joint_type_name(model->joints[i].type) + ")");
      Matrix3 R, R_dot, R_ddot;
      Vector3 p, p_dot, p_ddot;
      for (int r = 0; r < 3; ++r) {
        p[r] = value_of(path[i].p[r]);
        p_dot[r] = first_derivative(path[i].p[r]);
        p_ddot[r] = second_derivative(path[i].p[r]);
        for (int c = 0; c < 3; ++c) {
          R(r, c) = value_of(path[i].R(r, c));
          R_dot(r, c) = first_derivative(path[i].R(r, c));
          R_ddot(r, c) = second_derivative(path[i].R(r, c));
        }
      }
      // Motion subspace: the joint's own columns of link i, from the gradient poses.
      const Joint& joint = model->joints[i];
      for (int c = 0; c < joint.nv; ++c) {
        const int column = joint.v_index + c;
        Matrix3 dR;
        Vector3 dp;
        for (int r = 0; r < 3; ++r) {
          dp[r] = gradient_of(gradient[i].p[r], nv)[column];
          for (int k = 0; k < 3; ++k) dR(r, k) = gradient_of(gradient[i].R(r, k), nv)[column];
        }
        const Vector3 w = vee(dR * R.transpose());
        Vector6 expected;
        expected << w, dp - w.cross(p);
        EXPECT_LT(relative_error(data->motion_subspace_world.col(column), expected), 1e-12) << "column " << c;
      }
      const Vector3 w = vee(R_dot * R.transpose()), w_dot = vee(R_ddot * R.transpose() + R_dot * R_dot.transpose());
      Vector6 velocity, acceleration, analytic_acceleration = Vector6::Zero();
      velocity << w, p_dot - w.cross(p);
      acceleration << w_dot, p_ddot - w_dot.cross(p) - w.cross(p_dot);
      for (int j = i; j > 0; j = model->joints[j].parent)
        analytic_acceleration += data->bias_acceleration_world[j].vector();
      const Vector6 analytic_velocity = data->velocity_world[i].vector();
      EXPECT_LT(relative_error(analytic_velocity, velocity), 1e-12);
      // The acceleration at qdd = 0 is a sum of velocity products (v x v_J): its scale is
      // |v|^2 (times the lever arms), not its own size, which is zero for a link that
      // turns steadily about a fixed axis (both sides then give 0 to round-off).
      const double velocity_scale = std::max(1.0, velocity.cwiseAbs().maxCoeff());
      EXPECT_LT((analytic_acceleration - acceleration).cwiseAbs().maxCoeff(), 1e-12 * velocity_scale * velocity_scale)
          << analytic_acceleration.transpose() << "\n" << acceleration.transpose();
    }
  }
}

}  // namespace
}  // namespace heavesim

namespace heavesim {
namespace {

/// The expression constraint's function, written here in C++ for AutoDiffScalar: the same
/// formula as the text the kernel evaluates through muParser's bytecode and Taylor
/// arithmetic (app/case/coordinate_expression.hpp). Nonlinear in every coordinate, in t,
/// and mixed (x-t terms make J depend on t and give gamma its 2 f_xt . v and f_tt parts).
constexpr const char* cam_text = "a*sin(b) - c^2*cos(t) + 0.3*exp(0.2*a*t) + b*c*t - 0.5";
template <class S>
S cam_function(const S& a, const S& b, const S& c, const S& t) {
  using std::cos;
  using std::exp;
  using std::sin;
  return a * sin(b) - c * c * cos(t) + constant<S>(0.3) * exp(constant<S>(0.2) * a * t) + b * c * t -
         constant<S>(0.5);
}

TEST_F(ConstraintDerivativesAD, ExpressionConstraintJacobianVelocityTargetAndBias) {
  // A chain ground -revolute- arm -prismatic- slider -cylindrical- sleeve, and f over the
  // revolute's angle a, the prismatic's stroke b and the cylindrical's slide c
  // (coordinate 1), whose columns are v_index 0, 1 and 3.
  ModelBuilder builder;
  for (const char* body : {"arm", "slider", "sleeve"})
    builder.add_body({body, Inertia(1.0, Vector3(0.1, 0, 0), Matrix3::Identity() * 0.1), std::nullopt});
  JointDefinition joint;
  joint.name = "pivot", joint.kind = JointKind::revolute, joint.parent = "ground", joint.child = "arm";
  builder.add_joint(joint);
  joint.name = "rail", joint.kind = JointKind::prismatic, joint.parent = "arm", joint.child = "slider";
  builder.add_joint(joint);
  joint.name = "shaft", joint.kind = JointKind::cylindrical, joint.parent = "slider", joint.child = "sleeve";
  builder.add_joint(joint);
  const auto function = std::make_shared<const CoordinateExpression>(cam_text, std::vector<std::string>{"a", "b", "c"},
                                                                     std::map<std::string, double>{});
  builder.add_expression_constraint({"cam", {{"a", "pivot", {}}, {"b", "rail", {}}, {"c", "shaft", 1}}, function});
  const Model cam_model = builder.build();
  Data cam_data(cam_model);
  ASSERT_EQ(cam_model.num_constraint_rows, 1);
  EXPECT_STREQ(cam_model.constraints[0].kind_name(), "expression constraint");
  EXPECT_FALSE(cam_model.constraints[0].is_driver());
  const int columns[3] = {0, 1, 3};

  std::uniform_real_distribution<double> uniform(-1.5, 1.5);
  for (int trial = 0; trial < trials; ++trial) {
    VectorX q(cam_model.nq), v(cam_model.nv);
    for (int k = 0; k < q.size(); ++k) q[k] = uniform(random);
    for (int k = 0; k < v.size(); ++k) v[k] = uniform(random);
    const double t = time + uniform(random);
    update_positions(cam_model, cam_data, q);
    update_velocities(cam_model, cam_data, q, v);
    VectorX phi(1), nu(1), gamma(1);
    MatrixX J(1, cam_model.nv);
    constraint_residual(cam_model, cam_data, q, t, phi);
    constraint_jacobian(cam_model, cam_data, t, J);
    constraint_velocity_target(cam_model, cam_data, t, nu);
    constraint_bias(cam_model, cam_data, t, gamma);

    // J and nu: one AutoDiffScalar over (a, b, c, t).
    using Four = Eigen::AutoDiffScalar<Eigen::Vector4d>;
    const Four f = cam_function(Four(q[0], 4, 0), Four(q[1], 4, 1), Four(q[3], 4, 2), Four(t, 4, 3));
    VectorX J_expected = VectorX::Zero(cam_model.nv);
    for (int k = 0; k < 3; ++k) J_expected[columns[k]] = f.derivatives()[k];
    EXPECT_NEAR(phi[0], f.value(), 1e-14 * std::max(1.0, std::abs(f.value())));
    EXPECT_LT(relative_error(J.row(0).transpose(), J_expected), 1e-12) << J << "\n" << J_expected.transpose();
    EXPECT_NEAR(nu[0], -f.derivatives()[3], 1e-12 * std::max(1.0, std::abs(nu[0])));

    // gamma = -d2/dtau2 f(x + v tau, t + tau) at tau = 0 (qdd = 0): nested AD in tau.
    const SecondOrder tau = time_variable();
    auto along = [&](double x, double rate) -> SecondOrder {
      return constant<SecondOrder>(x) + tau * constant<SecondOrder>(rate);
    };
    const SecondOrder path = cam_function(along(q[0], v[0]), along(q[1], v[1]), along(q[3], v[3]), along(t, 1.0));
    EXPECT_NEAR(gamma[0], -second_derivative(path), 1e-12 * std::max(1.0, std::abs(gamma[0])));

    // Its load: J^T lambda on the coordinates it reads, nothing on the links.
    AlignedVector<Force> loads(cam_model.num_links(), Force::Zero());
    VectorX tau_generalized = VectorX::Zero(cam_model.nv);
    add_constraint_loads(cam_model, cam_data, t, VectorX::Constant(1, 2.5), loads, tau_generalized);
    EXPECT_LT(relative_error(tau_generalized, 2.5 * J_expected), 1e-12);
    for (const Force& load : loads) EXPECT_EQ(load.vector().norm(), 0.0);
  }
}

}  // namespace
}  // namespace heavesim
