// Closed loops through the application: an over-constrained case (redundant rows
// reported, resultant reaction exact), the DAE Newton matrix against finite
// differences of the residual, and singular configurations stopping with a diagnosis.
#include <gtest/gtest.h>

#include <filesystem>

#include "app/case/case_definition.hpp"
#include "app/run/simulation_run.hpp"
#include "app/scene/scene.hpp"
#include "kernel/algorithms/joint_reactions.hpp"
#include "kernel/system/ggl_dae_form.hpp"
#include "tests/test_support.hpp"

namespace heavesim {
namespace {

TEST(Loops, OverconstrainedCrownBlockReportsRedundancyAndCarriesTheWeight) {
  const CaseDefinition definition = load_case(testing::source_path("cases/overconstrained_crown_block.yaml"));
  Scene scene = build_scene(definition);
  const Model& model = *scene.model;
  // A fixed loop joint: 6 rows, of which only the vertical one is independent.
  EXPECT_EQ(model.num_constraint_rows, 6);
  EXPECT_EQ(scene.assembly.rank.rank, 1);
  EXPECT_EQ(scene.assembly.rank.redundant_rows.size(), 5u);
  const std::string redundant = describe_redundant_rows(model, scene.assembly.rank);
  EXPECT_NE(redundant.find("rotation about x"), std::string::npos) << redundant;
  EXPECT_EQ(redundant.find("translation along z"), std::string::npos) << redundant;

  // Give the rods a vertical kick so that the check covers motion, not only statics:
  // the total vertical load through the cylinders is then weight plus m a.
  const double total_mass = 20000.0 + 2 * 500.0, g = 9.81;
  const int a = model.joint_index("cylinder_a"), b = model.joint_index("cylinder_b");
  scene.initial_state[model.nq + model.joints[a].v_index] = 0.2;
  scene.initial_state[model.nq + model.joints[b].v_index] = 0.2;
  const VectorX kicked_state = scene.initial_state;
  // IDA (the case's) drops the redundant rows; HHT keeps all six (augmented Lagrangian).
  IntegratorSettings hht = definition.solver.integrator;
  hht.method = IntegrationMethod::hht;
  hht.step = 1e-3;
  for (const IntegratorSettings& settings : {definition.solver.integrator, hht}) {
    SCOPED_TRACE(integration_method_name(settings.method));
    scene.initial_state = kicked_state;
    auto integrator = make_integrator(settings, *scene.system);
    int samples = 0;
    run_simulation(scene, definition.solver, 0.05, *integrator, [&](double t, const VectorX& y) {
      scene.system->evaluate(t, y, true);
      const Data& data = scene.system->data();
      const Vector3 total = joint_reaction(model, data, a).force_world + joint_reaction(model, data, b).force_world;
      // Everything moves together vertically: sum of support forces = M (g + zdd).
      const double zdd = data.qdd[model.joints[a].v_index];
      EXPECT_NEAR(data.qdd[model.joints[b].v_index], zdd, 1e-9);
      EXPECT_NEAR(total.z(), total_mass * (g + zdd), 1e-9 * total_mass * g) << "t = " << t;
      EXPECT_NEAR(total.x(), 0.0, 1e-6);
      EXPECT_NEAR(total.y(), 0.0, 1e-6);
      EXPECT_NEAR(y[model.joints[a].q_index], y[model.joints[b].q_index], 1e-9);  // the rods move as one
      ++samples;
      return samples < 40;
    });
    EXPECT_EQ(samples, 40);
  }
}

/// dF/dy + cj dF/dy' of `system` at (t, y, yp) by central differences of its residual
/// (step 1e-6 in y and, unless cj = 0, in yp).
MatrixX residual_differences(GglDaeForm& system, double t, const VectorX& y, const VectorX& yp, double cj) {
  const auto n = y.size();
  MatrixX numeric(n, n);
  VectorX plus(n), minus(n);
  const double h = 1e-6;
  for (Eigen::Index k = 0; k < n; ++k) {
    VectorX y_plus = y, y_minus = y, yp_plus = yp, yp_minus = yp;
    y_plus[k] += h;
    y_minus[k] -= h;
    system.residual(t, y_plus, yp, plus);
    system.residual(t, y_minus, yp, minus);
    numeric.col(k) = (plus - minus) / (2 * h);
    if (cj == 0.0) continue;
    yp_plus[k] += h;
    yp_minus[k] -= h;
    system.residual(t, y, yp_plus, plus);
    system.residual(t, y, yp_minus, minus);
    numeric.col(k) += cj * (plus - minus) / (2 * h);
  }
  return numeric;
}

/// The GGL form's Newton matrix of `case_path` at a state moved away from the consistent
/// one, and central differences of its residual (step 1e-6 in y and in yp).
std::pair<MatrixX, MatrixX> newton_matrix_and_differences(const std::string& case_path) {
  const CaseDefinition definition = load_case(testing::source_path(case_path));
  Scene scene = build_scene(definition);
  GglDaeForm system(*scene.system);
  VectorX y, yp;
  system.dae_initial_values(0.0, scene.initial_state, y, yp);
  const int n = static_cast<int>(y.size());
  // Away from the consistent point, so that every term (including mu and the
  // velocity-dependent ones) is exercised.
  for (int i = 0; i < n; ++i) {
    y[i] += 0.05 * std::sin(1.0 + 3.0 * i);
    yp[i] += 0.3 * std::cos(2.0 + i);
  }
  const double cj = 7.5;
  MatrixX residual_y, residual_yp;
  EXPECT_TRUE(system.jacobian(0.3, y, yp, residual_y, residual_yp));
  const MatrixX analytic = residual_y + cj * residual_yp;
  return {analytic, residual_differences(system, 0.3, y, yp, cj)};
}

TEST(Loops, DaeNewtonMatrixMatchesFiniteDifferencesOfTheResidual) {
  // The slider-crank has a loop joint with redundant rows, a spring-damper and a push.
  const auto [analytic, numeric] = newton_matrix_and_differences("cases/validation/slider_crank.yaml");
  // The analytic matrix uses one-sided differences (step 1e-7) for the spring-damper
  // and the q-dependence of J^T lambda: agreement to ~1e-6 relative is what they give.
  EXPECT_LT((analytic - numeric).cwiseAbs().maxCoeff(), 1e-6 * numeric.cwiseAbs().maxCoeff())
      << "analytic\n" << analytic << "\nnumeric\n" << numeric;
}

TEST(Loops, RefreshedNewtonMatrixHasTheLoopBlocksOfTheNewState) {
  // IDA keeps a Newton matrix over several steps; the loops' blocks of dF/dy (J's rows and
  // columns) are brought up to the last residual's state once J has moved (refresh_jacobian).
  // Reference: central differences of the residual at the new state.
  const CaseDefinition definition = load_case(testing::source_path("cases/validation/slider_crank.yaml"));
  Scene scene = build_scene(definition);
  GglDaeForm system(*scene.system);
  VectorX y, yp;
  system.dae_initial_values(0.0, scene.initial_state, y, yp);
  const int n = static_cast<int>(y.size()), size = scene.system->size(), m = (n - size) / 2;
  ASSERT_GT(m, 0);
  MatrixX residual_y, residual_yp;
  ASSERT_TRUE(system.jacobian(0.0, y, yp, residual_y, residual_yp));
  const MatrixX before = residual_y;
  VectorX r(n);
  system.residual(0.0, y, yp, r);
  EXPECT_FALSE(system.refresh_jacobian(residual_y)) << "J has not moved";
  // The crank turned by 0.3 rad, the others moved a little, non-zero multipliers.
  for (int i = 0; i < n; ++i) y[i] += 0.02 * std::sin(1.0 + 3.0 * i);
  y[0] += 0.3;
  system.residual(0.0, y, yp, r);
  ASSERT_TRUE(system.refresh_jacobian(residual_y));
  const MatrixX numeric = residual_differences(system, 0.0, y, yp, 0.0);  // dF/dy alone
  const auto expect_near = [&](int row, int column, int rows, int columns, const char* what) {
    const MatrixX difference = residual_y.block(row, column, rows, columns) - numeric.block(row, column, rows, columns);
    const double block_scale = numeric.block(row, column, rows, columns).cwiseAbs().maxCoeff();
    EXPECT_LT(difference.cwiseAbs().maxCoeff(), 1e-7 * block_scale)
        << what << "\nrefreshed\n" << residual_y.block(row, column, rows, columns) << "\nnumeric\n"
        << numeric.block(row, column, rows, columns);
  };
  const int nq = scene.model->nq, nv = scene.model->nv;
  expect_near(0, size + m, nq, m, "dF_q/dmu = N J^T");
  expect_near(nq, size, nv, m, "dF_v/dlambda = -J^T");
  expect_near(size, nq, m, nv, "dF_lambda/dv = J");
  expect_near(size + m, 0, m, nq, "dF_mu/dq = J N+");
  // The costly blocks stay those of the first evaluation (the dynamics' derivatives).
  EXPECT_EQ(residual_y.block(nq, 0, nv, size), before.block(nq, 0, nv, size));
}

// The H1 rig: a free platform with hydrodynamic loads, a loop, two pneumatic compensators
// and the servo-valve cylinder, whose 5 states (spool, chamber pressures) are the only
// element states. Their columns come from the owning element alone
// (DynamicsDifferentiator); each column of the matrix is checked against its own scale,
// since the platform's entries (6e7 kg) would hide the hydraulic ones.
TEST(Loops, DaeNewtonMatrixWithElementStatesMatchesFiniteDifferences) {
  const auto [analytic, numeric] = newton_matrix_and_differences("cases/c4_irregular_waves/h1_active_hydraulic_3h.yaml");
  for (int k = 0; k < numeric.cols(); ++k) {
    const double scale = numeric.col(k).cwiseAbs().maxCoeff() + analytic.col(k).cwiseAbs().maxCoeff();
    EXPECT_LE((analytic.col(k) - numeric.col(k)).cwiseAbs().maxCoeff(), 1e-5 * scale) << "column " << k;
  }
}

TEST(Loops, SingularPassStopsWithADiagnosisNotANaN) {
  // The four-bars of IFToMM A02 lie flat at q = pi/2 + k pi, where the loop loses
  // rank. Where an integrator cannot pass (Dormand-Prince with the KKT solve at 1e-8;
  // IDA's GGL form at 1e-11 for N = 2, measured; it passes at 1e-10 since its Newton matrix
  // is kept within 30 % of cj, docs/physics/constraints-and-integration.md §5) it must stop
  // with exit code 3 and a diagnosis, leaving a readable, incomplete result file.
  for (const auto& [case_name, overrides] :
       {std::pair<std::string, std::string>{"iftomm_a02_n1", "solver.integrator=dopri5 --set solver.rtol=1e-8"},
        std::pair<std::string, std::string>{"iftomm_a02_n2", "solver.integrator=ida --set solver.rtol=1e-11"}}) {
    const std::string output =
        (std::filesystem::temp_directory_path() / ("heavesim_singular_" + case_name + ".h5")).string();
    const testing::CommandResult result = testing::run_command_line(
        testing::heavesim_binary() + " run -q " + testing::source_path("cases/validation/" + case_name + ".yaml") +
        " --set " + overrides + " -o " + output);
    EXPECT_EQ(result.exit_code, 3) << case_name << ": " << result.output;
    EXPECT_NE(result.output.find("numerical failure"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("suggestion"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("nan"), std::string::npos) << result.output;
    std::filesystem::remove(output);
  }
}

}  // namespace
}  // namespace heavesim
