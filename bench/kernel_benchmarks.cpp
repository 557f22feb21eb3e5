// Per-call cost of the kernel algorithms on the benchmark models (warm data, 1024
// pre-drawn random states cycled, no allocation). Run: build/bench/heavesim_bench.
#include <benchmark/benchmark.h>

#include <memory>
#include <random>

#include "cli/process_memory.hpp"
#include "samples/bench_models.hpp"
#include "samples/hanging_chain.hpp"
#include "kernel/algorithms/forward_dynamics.hpp"
#include "kernel/algorithms/joint_reactions.hpp"

namespace heavesim::bench {
namespace {

using samples::BenchModel;
using samples::BenchStates;

struct Workload {
  explicit Workload(const BenchModel& bench)
      : model(samples::to_model(bench)), data(model), states(samples::bench_states(model, 1024, 1)) {}
  Model model;
  Data data;
  BenchStates states;
};

BenchModel model_for(int index) {
  switch (index) {
    case 0: return samples::bench_double_pendulum();
    case 1: return samples::chain7();
    case 2: return samples::humanoid32();
    default: return samples::tree32_fixed();
  }
}

template <class Operation>
void run(benchmark::State& state, Operation operation) {
  static std::vector<std::unique_ptr<Workload>> workloads(4);
  const int index = static_cast<int>(state.range(0));
  if (!workloads[index]) workloads[index] = std::make_unique<Workload>(model_for(index));
  Workload& w = *workloads[index];
  state.SetLabel(model_for(index).name + " nv=" + std::to_string(w.model.nv));
  std::size_t k = 0;
  for (auto _ : state) {
    operation(w, k & 1023);
    benchmark::ClobberMemory();
    ++k;
  }
}

void BM_PositionStage(benchmark::State& state) {
  run(state, [](Workload& w, std::size_t k) {
    update_positions(w.model, w.data, w.states.q[k]);
    benchmark::DoNotOptimize(w.data.X_world_link.data());
  });
}
void BM_VelocityStage(benchmark::State& state) {
  run(state, [](Workload& w, std::size_t k) {
    if (k == 0) update_positions(w.model, w.data, w.states.q[0]);
    update_velocities(w.model, w.data, w.states.q[0], w.states.v[k]);
    benchmark::DoNotOptimize(w.data.velocity_world.data());
  });
}
void BM_InverseDynamicsPass(benchmark::State& state) {
  run(state, [](Workload& w, std::size_t k) {
    if (k == 0) {
      update_positions(w.model, w.data, w.states.q[0]);
      update_velocities(w.model, w.data, w.states.q[0], w.states.v[0]);
    }
    benchmark::DoNotOptimize(inverse_dynamics(w.model, w.data, w.states.tau[k]));
  });
}

void BM_RNEA(benchmark::State& state) {
  run(state, [](Workload& w, std::size_t k) {
    benchmark::DoNotOptimize(rnea(w.model, w.data, w.states.q[k], w.states.v[k], w.states.tau[k]));
  });
}
void BM_CRBA(benchmark::State& state) {
  run(state, [](Workload& w, std::size_t k) { benchmark::DoNotOptimize(crba(w.model, w.data, w.states.q[k])); });
}
void BM_ABA(benchmark::State& state) {
  run(state, [](Workload& w, std::size_t k) {
    benchmark::DoNotOptimize(aba(w.model, w.data, w.states.q[k], w.states.v[k], w.states.tau[k]));
  });
}
void BM_ForwardDynamicsCRBA(benchmark::State& state) {
  run(state, [](Workload& w, std::size_t k) {
    update_positions(w.model, w.data, w.states.q[k]);
    update_velocities(w.model, w.data, w.states.q[k], w.states.v[k]);
    benchmark::DoNotOptimize(composite_rigid_body_forward_dynamics(w.model, w.data, w.states.tau[k]));
  });
}
/// The reaction pass alone, after forward dynamics.
void BM_Reactions(benchmark::State& state) {
  run(state, [](Workload& w, std::size_t k) {
    if (k == 0) aba(w.model, w.data, w.states.q[0], w.states.v[0], w.states.tau[0]);
    compute_joint_wrenches(w.model, w.data);
    benchmark::DoNotOptimize(w.data.joint_wrench_world.data());
  });
}
/// A full evaluation as a recorded sample needs it: ABA then every joint reaction.
void BM_ABAWithReactions(benchmark::State& state) {
  run(state, [](Workload& w, std::size_t k) {
    aba(w.model, w.data, w.states.q[k], w.states.v[k], w.states.tau[k]);
    compute_joint_wrenches(w.model, w.data);
    benchmark::DoNotOptimize(w.data.joint_wrench_world.data());
  });
}

// The whole binary on the heap `heavesim` runs on (cli/process_memory.cpp), set before
// main whatever the filter or the order of the benchmarks: with glibc's defaults (128 KiB
// thresholds), BM_SetUp from 128 links on gave its pages back every iteration and faulted
// them in again, 0.67 ms at 128 links instead of 0.08, a step from 64 links that was page
// faults, not work (docs/performance.md, "Issue #18, twenty-fifth round").
[[maybe_unused]] const bool heap_as_heavesim_sets_it = (back_heap_with_huge_pages(), true);

/// Set-up of an n-link chain as a case builds it: the model through ModelBuilder
/// (samples::hanging_chain: names, joints, inertias, topology) and its Data (every
/// workspace sized once). Issue #18 asks for O(n) and at most 10 ms at 128 links;
/// Google Benchmark fits the exponent over n = 16 .. 1024.
void BM_SetUp(benchmark::State& state) {
  const std::vector<double> masses(static_cast<std::size_t>(state.range(0)), 10.0);
  for (auto _ : state) {
    const Model model = samples::hanging_chain(masses);
    Data data(model);
    benchmark::DoNotOptimize(data.q.data());
  }
  state.SetComplexityN(state.range(0));
  state.SetLabel("hanging chain, " + std::to_string(state.range(0)) + " links");
}
BENCHMARK(BM_SetUp)->RangeMultiplier(2)->Range(16, 1024)->Complexity();

#define HEAVESIM_MODELS ->Arg(0)->Arg(1)->Arg(2)->Arg(3)
BENCHMARK(BM_PositionStage) HEAVESIM_MODELS;
BENCHMARK(BM_VelocityStage) HEAVESIM_MODELS;
BENCHMARK(BM_InverseDynamicsPass) HEAVESIM_MODELS;
BENCHMARK(BM_RNEA) HEAVESIM_MODELS;
BENCHMARK(BM_CRBA) HEAVESIM_MODELS;
BENCHMARK(BM_ABA) HEAVESIM_MODELS;
BENCHMARK(BM_ForwardDynamicsCRBA) HEAVESIM_MODELS;
BENCHMARK(BM_Reactions) HEAVESIM_MODELS;
BENCHMARK(BM_ABAWithReactions) HEAVESIM_MODELS;

}  // namespace
}  // namespace heavesim::bench

BENCHMARK_MAIN();
