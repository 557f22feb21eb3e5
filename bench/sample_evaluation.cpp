// The recording's work a sample in the default drilling run (issue #18): what the thread
// that evaluates the samples beside the integration does for each of the 12,001 output
// times of `heavesim run cases/drilling.yaml`, timed in one process (a whole run's time
// on this shared machine varies by more than the parts below: docs/performance.md,
// "Issue #18, nineteenth round"). The states are the run's own: the case is integrated
// once, before timing, and (t, y) kept at every output time.
//  * drilling_sample_evaluation/reactions:1: MultibodySystem::evaluate(t, y, reactions) at
//    those states, one after another: kinematics, loads, the articulated-body accelerations
//    and the joints' reactions (as the run's channels ask); reactions:0 without them.
//  * drilling_sample_record/threads:1: the same states through Recorder::record on the
//    same scene, in line (the evaluation, then every channel into the sample's row, the
//    energy, the joint loads, and at every 1,024th sample the hand-over of a block to the
//    block writer and statistics threads), into a result file with the run's layout; one
//    iteration records the whole run. The recorder and file are made, and closed, untimed.
//    threads:2: the same with the samples evaluated beside, as in a run
//    (Recorder::evaluate_on_second_thread on a second build), this thread only copying
//    the states; threads:3: and this thread evaluating on a third build whenever the
//    samples' thread is busy, as a run's integrating thread does (here it has nothing else
//    to do, so it takes about half). Timed to the last sample recorded (record_queued_samples).
// Counters: seconds a sample (the evaluation thread's share of the run is 12,001 times
// it). Run:
//   build/bench/heavesim_sample_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/output/recorder.hpp"
#include "app/run/simulation_run.hpp"
#include "app/scene/scene.hpp"
#include "kernel/integrators/integrator.hpp"

namespace heavesim::bench {
namespace {

constexpr const char* case_path = HEAVESIM_SOURCE_DIR "/cases/drilling.yaml";

/// The drilling case and the run's (t, y) at every output time.
struct DrillingSamples {
  CaseDefinition definition = load_case(case_path);
  std::vector<double> times;
  std::vector<VectorX> states;

  DrillingSamples() {
    Scene integrated = build_scene(definition);
    const std::unique_ptr<Integrator> integrator = make_integrator(definition.solver.integrator, *integrated.system);
    run_simulation(integrated, definition.solver, definition.output.interval, *integrator,
                   [this](double t, const VectorX& y) {
                     times.push_back(t);
                     states.push_back(y);
                     return true;
                   });
  }
};

const DrillingSamples& drilling_samples() {
  static const DrillingSamples samples;
  return samples;
}

void drilling_sample_evaluation(benchmark::State& state) {
  const DrillingSamples& samples = drilling_samples();
  Scene scene = build_scene(samples.definition);
  const bool reactions = state.range(0) == 1;
  std::size_t k = 0;
  for (auto _ : state) {
    scene.system->evaluate(samples.times[k], samples.states[k], reactions);
    benchmark::DoNotOptimize(scene.system->data().qdd.data());
    if (++k == samples.times.size()) k = 0;
  }
  state.counters["per_sample"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void drilling_sample_record(benchmark::State& state) {
  const DrillingSamples& samples = drilling_samples();
  Scene scene = build_scene(samples.definition);
  Scene callers = build_scene(samples.definition);
  const int threads = static_cast<int>(state.range(0));
  const char* directory = std::getenv("HEAVESIM_BENCH_DIR");
  const std::string path =
      (std::filesystem::path(directory != nullptr ? directory : "/tmp") / "heavesim_sample_bench.h5").string();
  const auto sample_count = static_cast<hsize_t>(samples.times.size());
  std::optional<ResultFile> file;
  std::optional<Recorder> recorder;
  for (auto _ : state) {
    state.PauseTiming();
    recorder.reset();
    file.reset();  // closes the last iteration's file
    file.emplace(path, sample_count);
    recorder.emplace(samples.definition, scene, *file, nullptr);
    recorder->lay_out_file();  // in line, untimed: the samples alone are timed
    if (threads == 2) recorder->evaluate_on_second_thread();
    if (threads == 3) recorder->evaluate_on_second_thread(&callers);
    state.ResumeTiming();
    for (std::size_t k = 0; k < samples.times.size(); ++k) recorder->record(samples.times[k], samples.states[k]);
    recorder->record_queued_samples();
  }
  recorder.reset();  // after the timed loop: untimed
  file.reset();
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
  state.counters["per_sample"] = benchmark::Counter(static_cast<double>(state.iterations() * sample_count),
                                                    benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

BENCHMARK(drilling_sample_evaluation)->ArgName("reactions")->Arg(1)->Arg(0);
BENCHMARK(drilling_sample_record)->ArgName("threads")->Arg(1)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace heavesim::bench

BENCHMARK_MAIN();
