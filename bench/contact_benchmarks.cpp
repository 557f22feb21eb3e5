// Contact stepping (kernel/contact; docs/performance.md, "Contact stepping"):
//   BM_ContactStepStack/N   one velocity-level step of N stacked cubes at rest (4 points
//                           per face: 12 N rows), detection, Delassus matrix and solve;
//   BM_MassSolveDense/N and BM_MassSolveTree/N   M^-1 J^T for those rows by the dense
//                           Cholesky (one LLT and a solve per column) against the tree's
//                           L^T L (kernel/algorithms/tree_factorization): the ratio is
//                           the gain of the branch-induced sparsity on N free bodies.
#include <benchmark/benchmark.h>

#include "kernel/algorithms/mass_matrix.hpp"
#include "kernel/algorithms/tree_factorization.hpp"
#include "kernel/contact/contact_stepper.hpp"
#include "samples/contact_scenes.hpp"

namespace heavesim::bench {
namespace {

void BM_ContactStepStack(benchmark::State& state) {
  const int cubes = static_cast<int>(state.range(0));
  const samples::ContactScene scene = samples::box_stack(cubes, 1.0, 10.0, 1.0, 0.5);
  ContactStepper stepper(*scene.model, scene.contacts, 4 * cubes);
  Data data(*scene.model);
  VectorX q = scene.q, v = scene.v;
  const VectorX tau = VectorX::Zero(scene.model->nv);
  double t = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(stepper.step(data, t, 1e-2, q, v, tau).rows);
    t += 1e-2;
  }
}

/// The stack's contact Jacobian rows as columns J^T (nv x 12 N), from one step.
struct MassSolveWorkload {
  samples::ContactScene scene;
  Data data;
  MatrixX jacobian_t;
  explicit MassSolveWorkload(int cubes) : scene(samples::box_stack(cubes, 1.0, 10.0, 1.0, 0.5)), data(*scene.model) {
    update_positions(*scene.model, data, scene.q);
    mass_matrix(*scene.model, data);
    // Any rows with the contacts' sparsity do: unit normals and tangents at each face's
    // four corners, as the stepper builds them.
    jacobian_t = MatrixX::Zero(scene.model->nv, 12 * cubes);
    for (int column = 0; column < jacobian_t.cols(); ++column) {
      const int cube = column / 12;
      jacobian_t.block(6 * cube, column, 6, 1).setConstant(1.0 + 0.1 * (column % 12));
      if (cube > 0) jacobian_t.block(6 * (cube - 1), column, 6, 1).setConstant(-1.0);
    }
  }
};

void BM_MassSolveDense(benchmark::State& state) {
  MassSolveWorkload w(static_cast<int>(state.range(0)));
  MatrixX result = w.jacobian_t;
  Eigen::LLT<MatrixX> factor(w.data.mass_matrix.rows());
  for (auto _ : state) {
    factor.compute(w.data.mass_matrix);
    for (int c = 0; c < result.cols(); ++c) {
      auto column = result.col(c);
      column = w.jacobian_t.col(c);
      factor.solveInPlace(column);
    }
    benchmark::DoNotOptimize(result.data());
  }
}

void BM_MassSolveTree(benchmark::State& state) {
  MassSolveWorkload w(static_cast<int>(state.range(0)));
  const std::vector<int>& parent = w.scene.model->velocity_coordinate_parent;
  MatrixX factor = w.data.mass_matrix, result = w.jacobian_t;
  for (auto _ : state) {
    for (int i = 0; i < factor.rows(); ++i)
      for (int j = i; j >= 0; j = parent[j]) factor(i, j) = w.data.mass_matrix(i, j);
    factorize_tree(parent, factor);
    for (int c = 0; c < result.cols(); ++c) {
      auto column = result.col(c);
      column = w.jacobian_t.col(c);
      solve_tree(parent, factor, column);
    }
    benchmark::DoNotOptimize(result.data());
  }
}

BENCHMARK(BM_ContactStepStack)->Arg(5)->Arg(20);
BENCHMARK(BM_MassSolveDense)->Arg(5)->Arg(20);
BENCHMARK(BM_MassSolveTree)->Arg(5)->Arg(20);

}  // namespace
}  // namespace heavesim::bench

BENCHMARK_MAIN();
