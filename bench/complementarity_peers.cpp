// Complementarity solvers side by side with the peers (docs/performance.md): our Lemke,
// Dantzig and projected Gauss-Seidel (kernel/complementarity) against Bullet's
// btLemkeAlgorithm and btSolveDantzigLCP (BulletDynamics' MLCPSolvers, double precision)
// and Siconos-Numerics' lcp_lexicolemke, on the same random SPD and P-matrix problems
// (n = 50, 200; samples/complementarity_problems) and Murty's problem (n = 16).
//
// Before timing, every solver solves every problem once and the answers are compared
// (the same z to 1e-8 of |z|_inf, or the run stops); the table printed gives pivots and
// the relative natural-map residual of each. Then Google Benchmark times them, ours and
// the peers' registered one after the other for each problem (use
// --benchmark_enable_random_interleaving=true --benchmark_repetitions=N to alternate).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include <BulletDynamics/MLCPSolvers/btDantzigLCP.h>
#include <BulletDynamics/MLCPSolvers/btLemkeAlgorithm.h>
#include <numerics/LCP_Solvers.h>
#include <numerics/LinearComplementarityProblem.h>
#include <numerics/NumericsMatrix.h>
#include <numerics/SolverOptions.h>
#include <numerics/lcp_cst.h>

#include "kernel/complementarity/dantzig.hpp"
#include "kernel/complementarity/lemke.hpp"
#include "kernel/complementarity/projected_gauss_seidel.hpp"
#include "samples/complementarity_problems.hpp"

namespace {

using heavesim::MatrixX;
using heavesim::VectorX;

struct Case {
  std::string name;
  heavesim::samples::LcpSample sample;
  bool symmetric;
};

std::vector<Case>& cases() {
  static std::vector<Case> all = [] {
    std::vector<Case> list;
    for (const int n : {50, 200}) {
      list.push_back({"spd" + std::to_string(n), heavesim::samples::random_spd_lcp(n, 1000 + n), true});
      list.push_back({"pmatrix" + std::to_string(n), heavesim::samples::random_p_matrix_lcp(n, 2000 + n), false});
    }
    list.push_back({"murty16", heavesim::samples::murty_problem(16), false});
    return list;
  }();
  return all;
}

// ---- the solvers, each as "solve, return pivots/iterations, fill z" -------------------
struct Outcome {
  bool ok = false;
  int pivots = 0;
  VectorX z;
};

struct Ours {
  explicit Ours(int n) : lemke(n), dantzig(n), pgs(n), z(n) {}
  heavesim::LemkeWorkspace lemke;
  heavesim::DantzigWorkspace dantzig;
  heavesim::ProjectedGaussSeidelWorkspace pgs;
  VectorX z;
};

Outcome ours_lemke(const Case& c, Ours& ours) {
  heavesim::LemkeOptions options;
  options.max_pivots = 1 << 20;
  const auto result = heavesim::lemke({c.sample.M, c.sample.q}, ours.lemke, ours.z, options);
  return {result.solved(), result.pivots, ours.z};
}

Outcome ours_dantzig(const Case& c, Ours& ours) {
  const auto result = heavesim::dantzig({c.sample.M, c.sample.q}, ours.dantzig, ours.z);
  return {result.solved(), result.pivots, ours.z};
}

Outcome ours_pgs(const Case& c, Ours& ours) {
  heavesim::ProjectedGaussSeidelOptions options;
  options.max_iterations = 100000;
  const auto result = heavesim::projected_gauss_seidel({c.sample.M, c.sample.q}, ours.pgs, ours.z, options);
  return {result.solved(), result.iterations, ours.z};
}

// Bullet: btLemkeAlgorithm returns [w; z]; getSteps() leaves out the first and the last pivot.
struct BulletLemkeInput {
  btMatrixXu M;
  btVectorXu q;
};
BulletLemkeInput bullet_input(const Case& c) {
  const int n = static_cast<int>(c.sample.q.size());
  BulletLemkeInput input{btMatrixXu(n, n), btVectorXu(n)};
  for (int i = 0; i < n; ++i) {
    input.q[i] = c.sample.q[i];
    for (int j = 0; j < n; ++j) input.M.setElem(i, j, c.sample.M(i, j));
  }
  return input;
}

Outcome bullet_lemke(const BulletLemkeInput& input, int n) {
  btLemkeAlgorithm lemke(input.M, input.q, 0);
  const btVectorXu solution = lemke.solve(1u << 20);  // the default cap (100) fails at n = 200
  Outcome outcome{lemke.getInfo() == 0, lemke.getSteps() + 2, VectorX(n)};
  if (solution.rows() == 2 * n)
    for (int i = 0; i < n; ++i) outcome.z[i] = solution[n + i];
  return outcome;
}

// Bullet's (ODE's) Dantzig solves A x = b + w, lo <= x <= hi, and overwrites A and b.
struct BulletDantzigBuffers {
  std::vector<btScalar> A, A_copy, b, b_copy, x, w, lo, hi;
  std::vector<int> findex;
  btDantzigScratchMemory scratch;
};
BulletDantzigBuffers bullet_dantzig_buffers(const Case& c) {
  const int n = static_cast<int>(c.sample.q.size());
  BulletDantzigBuffers buffers;
  buffers.A.resize(n * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) buffers.A[i * n + j] = c.sample.M(i, j);
  buffers.b.resize(n);
  for (int i = 0; i < n; ++i) buffers.b[i] = -c.sample.q[i];
  buffers.A_copy = buffers.A;
  buffers.b_copy = buffers.b;
  buffers.x.assign(n, 0.0);
  buffers.w.assign(n, 0.0);
  buffers.lo.assign(n, 0.0);
  buffers.hi.assign(n, SIMD_INFINITY);
  buffers.findex.assign(n, -1);
  return buffers;
}

Outcome bullet_dantzig(BulletDantzigBuffers& buffers, int n) {
  std::memcpy(buffers.A_copy.data(), buffers.A.data(), sizeof(btScalar) * n * n);
  std::memcpy(buffers.b_copy.data(), buffers.b.data(), sizeof(btScalar) * n);
  std::fill(buffers.x.begin(), buffers.x.end(), 0.0);
  const bool ok = btSolveDantzigLCP(n, buffers.A_copy.data(), buffers.x.data(), buffers.b_copy.data(),
                                    buffers.w.data(), 0, buffers.lo.data(), buffers.hi.data(),
                                    buffers.findex.data(), buffers.scratch);
  Outcome outcome{ok, 0, VectorX(n)};
  for (int i = 0; i < n; ++i) outcome.z[i] = buffers.x[i];
  return outcome;
}

// Siconos: dense NumericsMatrix is column-major, as Eigen's.
struct SiconosInput {
  LinearComplementarityProblem problem{};
  SolverOptions* options = nullptr;
  std::vector<double> q, z, w;
};
SiconosInput* siconos_input(const Case& c) {
  const int n = static_cast<int>(c.sample.q.size());
  auto* input = new SiconosInput;
  double* data = static_cast<double*>(std::malloc(sizeof(double) * n * n));
  std::memcpy(data, c.sample.M.data(), sizeof(double) * n * n);
  input->q.assign(c.sample.q.data(), c.sample.q.data() + n);
  input->z.assign(n, 0.0);
  input->w.assign(n, 0.0);
  input->problem.size = n;
  input->problem.M = NM_create_from_data(NM_DENSE, n, n, data);
  input->problem.q = input->q.data();
  input->options = solver_options_create(SICONOS_LCP_LEMKE);
  input->options->iparam[SICONOS_IPARAM_MAX_ITER] = 1 << 20;
  return input;
}

Outcome siconos_lemke(SiconosInput& input, int n) {
  int info = 0;
  lcp_lexicolemke(&input.problem, input.z.data(), input.w.data(), &info, input.options);
  Outcome outcome{info == 0, input.options->iparam[SICONOS_IPARAM_ITER_DONE], VectorX(n)};
  for (int i = 0; i < n; ++i) outcome.z[i] = input.z[i];
  return outcome;
}

double residual(const Case& c, const VectorX& z) {
  const VectorX w = c.sample.M * z + c.sample.q;
  return z.cwiseMin(w).lpNorm<Eigen::Infinity>() / c.sample.q.lpNorm<Eigen::Infinity>();
}

// ---- agreement first ------------------------------------------------------------------
bool check_agreement() {
  bool all = true;
  std::printf("%-10s %-22s %8s %12s %12s\n", "problem", "solver", "pivots", "residual", "|z - z*|");
  for (const Case& c : cases()) {
    const int n = static_cast<int>(c.sample.q.size());
    Ours ours(n);
    const BulletLemkeInput bullet = bullet_input(c);
    BulletDantzigBuffers buffers = bullet_dantzig_buffers(c);
    SiconosInput* siconos = siconos_input(c);
    std::vector<std::pair<std::string, Outcome>> outcomes;
    outcomes.emplace_back("heavesim Lemke", ours_lemke(c, ours));
    outcomes.emplace_back("Bullet Lemke", bullet_lemke(bullet, n));
    outcomes.emplace_back("Siconos lexicolemke", siconos_lemke(*siconos, n));
    if (c.symmetric) {
      outcomes.emplace_back("heavesim Dantzig", ours_dantzig(c, ours));
      outcomes.emplace_back("Bullet Dantzig", bullet_dantzig(buffers, n));
      outcomes.emplace_back("heavesim PGS (sweeps)", ours_pgs(c, ours));
    }
    for (const auto& [name, outcome] : outcomes) {
      const double error = (outcome.z - c.sample.z).lpNorm<Eigen::Infinity>() / c.sample.z.lpNorm<Eigen::Infinity>();
      const bool agrees = outcome.ok && error <= 1e-8;
      all = all && agrees;
      std::printf("%-10s %-22s %8d %12.2e %12.2e %s\n", c.name.c_str(), name.c_str(), outcome.pivots,
                  residual(c, outcome.z), error, agrees ? "" : (outcome.ok ? "DISAGREES" : "FAILED"));
    }
  }
  return all;
}

// ---- timing ---------------------------------------------------------------------------
void register_all() {
  for (Case& c : cases()) {
    const int n = static_cast<int>(c.sample.q.size());
    const Case* problem = &c;
    benchmark::RegisterBenchmark(("Lemke/heavesim/" + c.name).c_str(), [problem, n](benchmark::State& state) {
      Ours ours(n);
      for (auto _ : state) benchmark::DoNotOptimize(ours_lemke(*problem, ours).pivots);
    })->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Lemke/bullet/" + c.name).c_str(), [problem, n](benchmark::State& state) {
      const BulletLemkeInput input = bullet_input(*problem);
      for (auto _ : state) benchmark::DoNotOptimize(bullet_lemke(input, n).pivots);
    })->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Lemke/siconos/" + c.name).c_str(), [problem, n](benchmark::State& state) {
      SiconosInput* input = siconos_input(*problem);
      for (auto _ : state) benchmark::DoNotOptimize(siconos_lemke(*input, n).pivots);
    })->Unit(benchmark::kMillisecond);
    if (!c.symmetric) continue;
    benchmark::RegisterBenchmark(("Dantzig/heavesim/" + c.name).c_str(), [problem, n](benchmark::State& state) {
      Ours ours(n);
      for (auto _ : state) benchmark::DoNotOptimize(ours_dantzig(*problem, ours).pivots);
    })->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Dantzig/bullet/" + c.name).c_str(), [problem, n](benchmark::State& state) {
      BulletDantzigBuffers buffers = bullet_dantzig_buffers(*problem);
      for (auto _ : state) benchmark::DoNotOptimize(bullet_dantzig(buffers, n).ok);
    })->Unit(benchmark::kMillisecond);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (!check_agreement()) {
    std::printf("agreement check failed: not timing\n");
    return 1;
  }
  register_all();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
