// Andrews' squeezing mechanism (cases/validation/iftomm_a03_andrews.yaml; Hairer &
// Wanner, Solving ODEs II, §VII.7; Test Set for IVP Solvers, problem `andrews`;
// IFToMM benchmark A03). (a) The case is Andrews' mechanism: at the initial state and
// at random states, heavesim's mass matrix, velocity terms, applied generalized forces
// (torque + spring) and loop residuals, read in the test set's coordinates, equal the
// closed forms M(q), f(q, qd), g(q) of the test set's problem description, written out
// below from those equations and nowhere else. (b) A run to t = 0.03 s reaches the
// published reference in mescd (validation/oracles/andrews_reference.hpp), in SI and
// in millimetre-gram-second units.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "app/case/case_definition.hpp"
#include "app/run/simulation_run.hpp"
#include "app/scene/scene.hpp"
#include "kernel/algorithms/constraint_equations.hpp"
#include "kernel/algorithms/generalized_force.hpp"
#include "kernel/algorithms/inverse_dynamics.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/algorithms/mass_matrix.hpp"
#include "tests/test_support.hpp"
#include "validation/oracles/andrews_reference.hpp"

namespace heavesim {
namespace {

using Vector7 = Eigen::Matrix<double, 7, 1>;
using Matrix7 = Eigen::Matrix<double, 7, 7>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

// The test set's data (SI), Hairer & Wanner Table 7.1.
constexpr double m1 = .04325, m2 = .00365, m3 = .02373, m4 = .00706, m5 = .07050, m6 = .00706, m7 = .05498;
constexpr double xa = -.06934, ya = -.00227, xb = -.03635, yb = .03273, xc = .014, yc = .072, c0 = 4530;
constexpr double i1 = 2.194e-6, i2 = 4.410e-7, i3 = 5.255e-6, i4 = 5.667e-7, i5 = 1.169e-5, i6 = 5.667e-7,
                 i7 = 1.912e-5;
constexpr double d = 28e-3, da = 115e-4, e = 2e-2, ea = 1421e-5, rr = 7e-3, ra = 92e-5, l0 = 7785e-5;
constexpr double ss = 35e-3, sa = 1874e-5, sb = 1043e-5, sc = 18e-3, sd = 2e-2, ta = 2308e-5, tb = 916e-5;
constexpr double u = 4e-2, ua = 1228e-5, ub = 449e-5, zf = 2e-2, zt = 4e-2, fa = 1421e-5, mom = 33e-3;

/// The case's joints in the test set's coordinate order (beta, Theta, gamma, Phi,
/// delta, Omega, epsilon): the map is the identity up to this order.
constexpr const auto& joint_names = oracle::andrews_joint_names;

/// M(q) of the test set (symmetric; only Theta, Phi, Omega enter).
Matrix7 mass_matrix_closed_form(const Vector7& q) {
  const double cos_theta = std::cos(q[1]), sin_phi = std::sin(q[3]), sin_omega = std::sin(q[5]);
  Matrix7 M = Matrix7::Zero();
  M(0, 0) = m1 * ra * ra + m2 * (rr * rr - 2 * da * rr * cos_theta + da * da) + i1 + i2;
  M(1, 0) = M(0, 1) = m2 * (da * da - da * rr * cos_theta) + i2;
  M(1, 1) = m2 * da * da + i2;
  M(2, 2) = m3 * (sa * sa + sb * sb) + i3;
  M(3, 3) = m4 * (e - ea) * (e - ea) + i4;
  M(4, 3) = M(3, 4) = m4 * ((e - ea) * (e - ea) + zt * (e - ea) * sin_phi) + i4;
  M(4, 4) = m4 * (zt * zt + 2 * zt * (e - ea) * sin_phi + (e - ea) * (e - ea)) + m5 * (ta * ta + tb * tb) + i4 + i5;
  M(5, 5) = m6 * (zf - fa) * (zf - fa) + i6;
  M(6, 5) = M(5, 6) = m6 * ((zf - fa) * (zf - fa) - u * (zf - fa) * sin_omega) + i6;
  M(6, 6) = m6 * ((zf - fa) * (zf - fa) - 2 * u * (zf - fa) * sin_omega + u * u) + m7 * (ua * ua + ub * ub) + i6 + i7;
  return M;
}

/// The test set's f(q, qd) split into its applied part (the torque on beta, the spring
/// on gamma) and its velocity part (-C(q, qd)): M qdd = f - G^T lambda.
struct TestSetForces {
  Vector7 applied, velocity_terms;
};
TestSetForces forces_closed_form(const Vector7& q, const Vector7& qd) {
  TestSetForces f{Vector7::Zero(), Vector7::Zero()};
  // The spring from C to D = B + sd (cos g, sin g) + sc (sin g, -cos g): the force on D
  // is -c0 (L - l0) (D - C) / L; its generalized force on gamma is that dotted with dD/dgamma.
  const double gamma = q[2];
  const double xd = sd * std::cos(gamma) + sc * std::sin(gamma) + xb;
  const double yd = sd * std::sin(gamma) - sc * std::cos(gamma) + yb;
  const double length = std::hypot(xd - xc, yd - yc);
  const double scale = -c0 * (length - l0) / length;
  f.applied[0] = mom;
  f.applied[2] = scale * (xd - xc) * (sc * std::cos(gamma) - sd * std::sin(gamma)) +
                 scale * (yd - yc) * (sd * std::cos(gamma) + sc * std::sin(gamma));
  const double beta_dot = qd[0], theta_dot = qd[1], phi_dot = qd[3], delta_dot = qd[4], omega_dot = qd[5],
               epsilon_dot = qd[6];
  f.velocity_terms[0] = -m2 * da * rr * theta_dot * (theta_dot + 2 * beta_dot) * std::sin(q[1]);
  f.velocity_terms[1] = m2 * da * rr * beta_dot * beta_dot * std::sin(q[1]);
  f.velocity_terms[3] = m4 * zt * (e - ea) * delta_dot * delta_dot * std::cos(q[3]);
  f.velocity_terms[4] = -m4 * zt * (e - ea) * phi_dot * (phi_dot + 2 * delta_dot) * std::cos(q[3]);
  f.velocity_terms[5] = -m6 * u * (zf - fa) * epsilon_dot * epsilon_dot * std::cos(q[5]);
  f.velocity_terms[6] = m6 * u * (zf - fa) * omega_dot * (omega_dot + 2 * epsilon_dot) * std::cos(q[5]);
  return f;
}

/// g(q) of the test set: point E reached through the rod minus E reached through the
/// triangle (g1, g2), link 4 (g3, g4) and link 6 (g5, g6) [m].
Vector6 loop_residual_closed_form(const Vector7& q) {
  const double beta = q[0], theta = q[1], gamma = q[2], phi = q[3], delta = q[4], omega = q[5], epsilon = q[6];
  const double ex = rr * std::cos(beta) - d * std::cos(beta + theta);
  const double ey = rr * std::sin(beta) - d * std::sin(beta + theta);
  Vector6 g;
  g << ex - ss * std::sin(gamma) - xb, ey + ss * std::cos(gamma) - yb,
      ex - e * std::sin(phi + delta) - zt * std::cos(delta) - xa,
      ey + e * std::cos(phi + delta) - zt * std::sin(delta) - ya,
      ex - zf * std::cos(omega + epsilon) - u * std::sin(epsilon) - xa,
      ey - zf * std::sin(omega + epsilon) + u * std::cos(epsilon) - ya;
  return g;
}

/// The case loaded with its model and the map from the test set's coordinates to v.
struct AndrewsScene {
  explicit AndrewsScene(const std::string& relative_path, const std::vector<std::string>& overrides = {})
      : definition(load_case(testing::source_path(relative_path), overrides)), scene(build_scene(definition)) {
    const Model& model = *scene.model;
    EXPECT_EQ(model.nq, 7);
    EXPECT_EQ(model.nv, 7);
    for (int i = 0; i < 7; ++i) {
      const int joint = model.joint_index(joint_names[i]);
      EXPECT_GT(joint, 0) << joint_names[i];
      velocity_index[i] = model.joints[joint].v_index;
      EXPECT_EQ(model.joints[joint].q_index, velocity_index[i]);  // revolute: q and v line up
    }
  }
  VectorX to_heavesim(const Vector7& test_set) const {
    VectorX out(7);
    for (int i = 0; i < 7; ++i) out[velocity_index[i]] = test_set[i];
    return out;
  }
  Vector7 to_test_set(const VectorX& heavesim) const {
    Vector7 out;
    for (int i = 0; i < 7; ++i) out[i] = heavesim[velocity_index[i]];
    return out;
  }
  CaseDefinition definition;
  Scene scene;
  std::array<int, 7> velocity_index{};
};

/// The initial state, then random states near it (not on the constraint manifold: the
/// closed forms hold anywhere).
std::vector<std::pair<Vector7, Vector7>> sample_states() {
  std::vector<std::pair<Vector7, Vector7>> states;
  Vector7 q0;
  for (int i = 0; i < 7; ++i) q0[i] = oracle::andrews_initial_positions[i];
  states.emplace_back(q0, Vector7::Zero());
  std::mt19937 generator(20261124);
  std::uniform_real_distribution<double> angle(-1.5, 1.5), rate(-1500.0, 1500.0);  // rad, rad/s (the run reaches ~1400)
  for (int k = 0; k < 6; ++k) {
    Vector7 q, qd;
    for (int i = 0; i < 7; ++i) q[i] = q0[i] + angle(generator), qd[i] = rate(generator);
    states.emplace_back(q, qd);
  }
  return states;
}

TEST(Andrews, CaseIsAndrewsMechanismInTheTestSetsCoordinates) {
  AndrewsScene andrews("cases/validation/iftomm_a03_andrews.yaml");
  const Model& model = *andrews.scene.model;
  MultibodySystem& system = *andrews.scene.system;
  Data data(model);
  AlignedVector<Force> subtree_forces(model.num_links(), Force::Zero());
  VectorX generalized(model.nv), residual(model.num_constraint_rows);
  for (const auto& [q_test_set, qd_test_set] : sample_states()) {
    SCOPED_TRACE(::testing::Message() << "q = " << q_test_set.transpose() << ", qd = " << qd_test_set.transpose());
    const VectorX q = andrews.to_heavesim(q_test_set), v = andrews.to_heavesim(qd_test_set);

    // M(q): CRBA, read in the test set's order. Tolerance: round-off of sums of terms
    // up to ~1e-4 kg m^2 (the largest entry is ~1e-4).
    const MatrixX& M = crba(model, data, q);
    Matrix7 M_test_set;
    for (int i = 0; i < 7; ++i)
      for (int j = 0; j < 7; ++j) M_test_set(i, j) = M(andrews.velocity_index[i], andrews.velocity_index[j]);
    const Matrix7 M_closed = mass_matrix_closed_form(q_test_set);
    EXPECT_LT((M_test_set - M_closed).cwiseAbs().maxCoeff(), 1e-12 * M_closed.cwiseAbs().maxCoeff())
        << "heavesim:\n" << M_test_set << "\nclosed form:\n" << M_closed;

    // Velocity terms: -C(q, qd) by RNEA with qdd = 0 (no gravity in the case).
    const VectorX C = rnea(model, data, q, v, VectorX::Zero(model.nv));
    const TestSetForces closed = forces_closed_form(q_test_set, qd_test_set);
    const Vector7 velocity_terms = -andrews.to_test_set(C);
    EXPECT_LT((velocity_terms - closed.velocity_terms).cwiseAbs().maxCoeff(),
              1e-12 * std::max(closed.velocity_terms.cwiseAbs().maxCoeff(), 1e-12))
        << "heavesim: " << velocity_terms.transpose() << "\nclosed form: " << closed.velocity_terms.transpose();

    // Applied generalized forces: the case's elements (torque, spring) on the system's
    // stages, projected on the coordinates (Q = tau + sum J^T f).
    VectorX y = VectorX::Zero(system.size());
    y.head(model.nq) = q;
    y.segment(model.nq, model.nv) = v;
    system.compute_stages_and_forces(0.0, y);
    const AppliedForces& applied = system.applied_forces();
    generalized_applied_force(model, system.data(), applied.external_force_world, applied.joint_force, subtree_forces,
                              generalized);
    const Vector7 applied_test_set = andrews.to_test_set(generalized);
    EXPECT_LT((applied_test_set - closed.applied).cwiseAbs().maxCoeff(), 1e-12 * closed.applied.cwiseAbs().maxCoeff())
        << "heavesim: " << applied_test_set.transpose() << "\nclosed form: " << closed.applied.transpose();

    // g(q): each loop joint's rows "translation along x, y" of its frame A (on the
    // rod, at E) are d_A . (p_B - p_A); in the world p_A - p_B = -R_A (rows), which is
    // E through the rod minus E through the other body, the test set's pair.
    update_positions(model, data, q);
    constraint_residual(model, data, q, 0.0, residual);
    Vector6 g;
    ASSERT_EQ(model.constraints.size(), 3u);
    const std::array<const char*, 3> loops = {"loop_triangle", "loop_link4", "loop_link6"};
    for (int c = 0; c < 3; ++c) {
      const Constraint* loop = nullptr;
      for (const Constraint& constraint : model.constraints)
        if (constraint.name == loops[c]) loop = &constraint;
      ASSERT_NE(loop, nullptr) << loops[c];
      Vector3 along = Vector3::Zero();
      int found = 0;
      for (std::size_t r = 0; r < loop->rows.size(); ++r)
        if (loop->rows[r].kind == ConstraintRowKind::along) {
          along[loop->rows[r].axis_a] = residual[loop->first_row + static_cast<int>(r)];
          ++found;
        }
      EXPECT_EQ(found, 3);
      const Vector3 a_minus_b = -(constraint_frame_a(data, *loop).rotation() * along);
      EXPECT_NEAR(along.z(), 0.0, 1e-15);  // the mechanism stays in its plane
      g.segment<2>(2 * c) = a_minus_b.head<2>();
    }
    const Vector6 g_closed = loop_residual_closed_form(q_test_set);
    // Tolerance: round-off of sums of ~0.1 m terms.
    EXPECT_LT((g - g_closed).cwiseAbs().maxCoeff(), 1e-15 + 1e-12 * g_closed.cwiseAbs().maxCoeff())
        << "heavesim: " << g.transpose() << "\nclosed form: " << g_closed.transpose();
  }
}

TEST(Andrews, InitialStateIsTheTestSetsConsistentOne) {
  // The assembly onto the loops keeps the published consistent angles (to round-off).
  AndrewsScene andrews("cases/validation/iftomm_a03_andrews.yaml");
  const Vector7 q0 = andrews.to_test_set(andrews.scene.initial_state.head(7));
  for (int i = 0; i < 7; ++i) EXPECT_NEAR(q0[i], oracle::andrews_initial_positions[i], 1e-14) << joint_names[i];
  EXPECT_LT(loop_residual_closed_form(q0).cwiseAbs().maxCoeff(), 1e-15);
}

/// mescd at t = 0.03 s of a run of the case (with `overrides`).
double mescd_of_run(const std::string& relative_path, const std::vector<std::string>& overrides) {
  AndrewsScene andrews(relative_path, overrides);
  const CaseDefinition& definition = andrews.definition;
  Scene& scene = andrews.scene;
  auto integrator = make_integrator(definition.solver.integrator, *scene.system);
  VectorX last;
  double last_time = -1.0;
  const RunOutcome outcome =
      run_simulation(scene, definition.solver, definition.output.interval, *integrator, [&](double t, const VectorX& y) {
        last = y;
        last_time = t;
        return true;
      });
  EXPECT_TRUE(outcome.completed);
  EXPECT_NEAR(last_time, oracle::andrews_end_time, 1e-12);
  std::array<double, 7> computed{};
  const Vector7 angles = andrews.to_test_set(last.head(7));
  for (int i = 0; i < 7; ++i) computed[i] = angles[i];
  return oracle::mixed_error_significant_digits(computed, oracle::andrews_reference_positions);
}

TEST(Andrews, RunReachesTheTestSetReference) {
  // mescd as the test set defines it (validation/oracles/andrews_reference.hpp), over
  // the 7 positions, atol/rtol = 1.
  const double digits = mescd_of_run("cases/validation/iftomm_a03_andrews.yaml", {});
  EXPECT_GE(digits, 6.0);
  RecordProperty("mescd_si", std::to_string(digits));
}

TEST(Andrews, RunInMillimetreGramSecondReachesTheSameReference) {
  // Angles and time do not change with the units of length and mass.
  const double digits = mescd_of_run("cases/validation/iftomm_a03_andrews_mm_g.yaml", {});
  EXPECT_GE(digits, 6.0);
  RecordProperty("mescd_mm_g", std::to_string(digits));
}

}  // namespace
}  // namespace heavesim
