// heavesim sweep (docs/sweeps.md): the index is the same whatever the parallelism (serial,
// -j 2, mpirun -n 3), a run of the sweep equals the same case run by hand, a run that
// fails is recorded and the sweep completes, a resumed sweep reruns nothing and a changed
// variable reruns only its runs; the plan (grid order, Latin hypercube strata, scatter
// probabilities) against what the test computes itself; the worker pool records a
// crashed worker's task and goes on.
#include <gtest/gtest.h>

#include <csignal>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "app/sweep/run_record.hpp"
#include "app/sweep/sweep_plan.hpp"
#include "app/sweep/sweep_schema.hpp"
#include "app/sweep/task_distribution.hpp"
#include "io/hdf5/hdf5_reader.hpp"
#include "tests/app/documented_keys.hpp"
#include "tests/test_support.hpp"

namespace heavesim {
namespace {

using testing::heavesim_binary;
using testing::run_command_line;
using testing::source_path;

std::string scratch(const std::string& name) {
  const std::string directory = ::testing::TempDir() + "sweep_" + name;
  std::filesystem::remove_all(directory);
  return directory;
}

testing::CommandResult sweep(const std::string& file, const std::string& directory, const std::string& extra = "") {
  return run_command_line("timeout 120 " + heavesim_binary() + " sweep " + file + " -o " + directory + " " + extra);
}

/// Every dataset of an index file: numbers (NaN compared as equal by their bits) or texts.
struct IndexContents {
  std::map<std::string, std::vector<double>> numbers;
  std::map<std::string, std::vector<std::string>> texts;
};

IndexContents read_index(const std::string& path) {
  const hdf5::Reader file(path, "a sweep index");
  IndexContents contents;
  for (const std::string& dataset : file.datasets()) {
    if (dataset.starts_with("/runs/status") || dataset.starts_with("/runs/result_file") ||
        dataset.starts_with("/runs/hash") || dataset.starts_with("/runs/message") || dataset == "/runs/base_case")
      contents.texts[dataset] = file.read_strings(dataset);
    else
      contents.numbers[dataset] = file.read(dataset).values;
  }
  return contents;
}

/// What differs between two runs of the same case by timing alone.
bool timing(const std::string& dataset) {
  return dataset == "/runs/wall_time_s" || dataset == "/runs/rank_or_worker" || dataset == "/summary/wall_time_s" ||
         dataset == "/summary/real_time_factor";
}

void expect_same_index(const IndexContents& a, const IndexContents& b, const std::string& label) {
  SCOPED_TRACE(label);
  ASSERT_EQ(a.texts, b.texts);
  ASSERT_EQ(a.numbers.size(), b.numbers.size());
  for (const auto& [dataset, values] : a.numbers) {
    if (timing(dataset)) continue;
    const auto other = b.numbers.find(dataset);
    ASSERT_NE(other, b.numbers.end()) << dataset;
    ASSERT_EQ(values.size(), other->second.size()) << dataset;
    for (std::size_t i = 0; i < values.size(); ++i)
      EXPECT_TRUE(values[i] == other->second[i] || (std::isnan(values[i]) && std::isnan(other->second[i])))
          << dataset << "[" << i << "]: " << values[i] << " vs " << other->second[i];
  }
}

// The one longer test (about 10 s on 2 cores): 36 runs three times.
TEST(Sweep, SerialTwoWorkersAndThreeMpiRanksWriteIdenticalIndexes) {
  const std::string file = source_path("tests/cases/sweeps/c2_grid.yaml");
  const std::string serial = scratch("grid_serial"), pool = scratch("grid_j2"), mpi = scratch("grid_mpi");
  const auto one = sweep(file, serial, "-q");
  ASSERT_EQ(one.exit_code, 0) << one.output;
  const auto two = sweep(file, pool, "-q -j 2");
  ASSERT_EQ(two.exit_code, 0) << two.output;
  const auto ranks = run_command_line("timeout 120 mpirun --oversubscribe --allow-run-as-root -n 3 " + heavesim_binary() +
                                      " sweep " + file + " -o " + mpi + " -q");
  ASSERT_EQ(ranks.exit_code, 0) << ranks.output;

  const IndexContents a = read_index(serial + "/index.h5"), b = read_index(pool + "/index.h5"),
                      c = read_index(mpi + "/index.h5");
  expect_same_index(a, b, "serial vs -j 2");
  expect_same_index(a, c, "serial vs mpirun -n 3");
  // The work was shared: both workers and all three ranks ran some of the 36 runs.
  const auto& workers = b.numbers.at("/runs/rank_or_worker");
  EXPECT_EQ(std::set<double>(workers.begin(), workers.end()), (std::set<double>{0, 1}));
  const auto& mpi_ranks = c.numbers.at("/runs/rank_or_worker");
  EXPECT_EQ(std::set<double>(mpi_ranks.begin(), mpi_ranks.end()), (std::set<double>{0, 1, 2}));

  // The grid in plan order, written here: Z outermost (0.5 ... 1.5 by 0.2), T fastest.
  const auto& z = a.numbers.at("/variables/parameters.Z");
  const auto& t = a.numbers.at("/variables/parameters.T");
  ASSERT_EQ(z.size(), 36u);
  for (std::size_t i = 0; i < 36; ++i) {
    EXPECT_NEAR(z[i], 0.5 + 0.2 * static_cast<double>(i / 6), 1e-15) << i;
    EXPECT_EQ(t[i], 6.0 + 2.0 * static_cast<double>(i % 6)) << i;
    EXPECT_EQ(a.texts.at("/runs/status")[i], "complete") << i;
  }
  // A run of the sweep is the case run by hand with the same overrides: the same steps
  // and the same statistics (run 13: Z = 0.9, T = 8).
  const std::string by_hand = serial + "/by_hand.h5";
  const auto manual = run_command_line(heavesim_binary() + " run " + source_path("cases/c2_prescribed_heave/h0_passive.yaml") +
                                       " -q -o " + by_hand +
                                       " --set solver.t_end=2 --set output.interval=0.1 --set output.evaluate_after=1"
                                       " --set parameters.Z=0.9 --set parameters.T=8");
  ASSERT_EQ(manual.exit_code, 0) << manual.output;
  const hdf5::Reader reference(by_hand, "result");
  EXPECT_EQ(a.numbers.at("/summary/integrator_steps")[13], reference.number_attribute("/summary", "integrator_steps").value());
  const std::vector<double> q = reference.read("/joints/compensator/q").values;
  double largest = -INFINITY;
  for (std::size_t i = 10; i < q.size(); ++i) largest = std::max(largest, q[i]);  // t >= 1 s
  EXPECT_EQ(a.numbers.at("/statistics/joints.compensator.q/window_maximum")[13], largest);
  EXPECT_EQ(a.numbers.at("/statistics/joints.compensator.q/mpm_duration")[13], 3600.0);
}

TEST(Sweep, ARunThatFailsIsRecordedWithItsMessageAndTheSweepCompletes) {
  const std::string directory = scratch("fault");
  const auto result = sweep(source_path("tests/cases/sweeps/damper_fault.yaml"), directory);
  EXPECT_EQ(result.exit_code, 4) << result.output;  // some runs failed (docs/sweeps.md)
  const IndexContents index = read_index(directory + "/index.h5");
  EXPECT_EQ(index.texts.at("/runs/status"), (std::vector<std::string>{"complete", "numerical_failure", "complete"}));
  EXPECT_EQ(index.numbers.at("/runs/exit_code"), (std::vector<double>{0, 3, 0}));
  const std::string& message = index.texts.at("/runs/message")[1];
  EXPECT_NE(message.find("heavesim: numerical failure"), std::string::npos) << message;
  EXPECT_EQ(index.texts.at("/runs/message")[0], "");
  EXPECT_NE(result.output.find("run_0001"), std::string::npos) << result.output;
  // The whole stderr of the run is in its log; the failed run's summary is NaN.
  std::ifstream log(directory + "/logs/run_0001.log");
  const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("suggestion:"), std::string::npos) << text;
  EXPECT_TRUE(std::isnan(index.numbers.at("/summary/integrator_steps")[1]));
  EXPECT_GT(index.numbers.at("/summary/integrator_steps")[0], 0.0);
}

std::map<std::string, std::filesystem::file_time_type> result_times(const std::string& directory) {
  std::map<std::string, std::filesystem::file_time_type> times;
  for (const auto& entry : std::filesystem::directory_iterator(directory + "/runs"))
    times[entry.path().filename().string()] = entry.last_write_time();
  return times;
}

TEST(Sweep, AResumedSweepRerunsNothingAndAChangedVariableOnlyItsRuns) {
  const std::string directory = scratch("resume");
  std::filesystem::create_directories(directory);
  const std::string sweep_file = directory + "/scatter.yaml";
  auto write_sweep = [&](const std::string& second_area) {
    std::ofstream out(sweep_file);
    out << "base: " << source_path("cases/c2_prescribed_heave/h0_passive.yaml") << "\n"
        << "set: {solver.t_end: 2, output.interval: 0.1}\n"
        << "variables:\n  - {path: parameters.A_p, values: [0.1735, " << second_area << "]}\n"
        << "scatter: {file: " << source_path("tests/cases/sweeps/scatter_small.txt")
        << ", hs: parameters.Z, tp: parameters.T}\n";
  };
  write_sweep("0.2");
  const auto first = sweep(sweep_file, directory + "/out", "-j 2");
  ASSERT_EQ(first.exit_code, 0) << first.output;
  const auto before = result_times(directory + "/out");
  ASSERT_EQ(before.size(), 14u);  // 2 variants x the 7 sea states that occur

  const auto again = sweep(sweep_file, directory + "/out", "-j 2");
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_NE(again.output.find("14 complete (14 already complete, not rerun)"), std::string::npos) << again.output;
  EXPECT_EQ(result_times(directory + "/out"), before);

  write_sweep("0.21");  // the second variant changes: its 7 runs rerun, the first 7 do not
  const auto changed = sweep(sweep_file, directory + "/out", "-j 2");
  ASSERT_EQ(changed.exit_code, 0) << changed.output;
  EXPECT_NE(changed.output.find("(7 already complete, not rerun)"), std::string::npos) << changed.output;
  const auto after = result_times(directory + "/out");
  int rerun = 0;
  for (const auto& [name, time] : after) {
    const bool first_variant = name < "run_0007";
    EXPECT_EQ(time == before.at(name), first_variant) << name;
    rerun += time != before.at(name);
  }
  EXPECT_EQ(rerun, 7);

  // --no-resume reruns everything.
  const auto all = sweep(sweep_file, directory + "/out", "-j 2 --no-resume");
  EXPECT_NE(all.output.find("(0 already complete, not rerun)"), std::string::npos) << all.output;
}

TEST(Sweep, ScatterRunsEverySeaStateThatOccursWithItsProbability) {
  const std::string directory = scratch("scatter");
  const auto result = sweep(source_path("tests/cases/sweeps/c2_scatter.yaml"), directory, "-q -j 2");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const IndexContents index = read_index(directory + "/index.h5");
  // The table (tests/cases/sweeps/scatter_small.txt) written out here: Hs, Tp, count of
  // the non-zero cells in row order; the counts sum to 1000.
  const double cells[7][3] = {{0.5, 6, 100}, {0.5, 8, 200}, {1.5, 6, 50}, {1.5, 8, 400},
                              {1.5, 10, 150}, {2.5, 8, 60}, {2.5, 10, 40}};
  ASSERT_EQ(index.numbers.at("/scatter/probability").size(), 14u);
  for (std::size_t i = 0; i < 14; ++i) {
    const auto& cell = cells[i % 7];
    EXPECT_EQ(index.numbers.at("/variables/Hs")[i], cell[0]) << i;
    EXPECT_EQ(index.numbers.at("/variables/Tp")[i], cell[1]) << i;
    EXPECT_DOUBLE_EQ(index.numbers.at("/scatter/probability")[i], cell[2] / 1000.0) << i;
    EXPECT_EQ(index.numbers.at("/variables/parameters.A_p")[i], i < 7 ? 0.1735 : 0.2) << i;
  }
  const hdf5::Reader file(directory + "/index.h5", "index");
  EXPECT_EQ(file.text_attribute("/variables/Hs", "path").value(), "parameters.Z");
  EXPECT_EQ(file.number_attribute("/", "complete").value(), 1.0);
  EXPECT_EQ(file.number_attribute("/", "run_count").value(), 14.0);
  EXPECT_NE(file.text_attribute("/", "scatter_file").value().find("scatter_small.txt"), std::string::npos);
  // The CSV holds the same rows.
  std::ifstream csv(directory + "/index.csv");
  std::string header, line;
  std::getline(csv, header);
  EXPECT_NE(header.find("Hs [m],Tp [s],probability"), std::string::npos) << header;
  int rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 14);
}

TEST(Sweep, LatinHypercubeSamplesEveryStratumOfEveryVariableOnce) {
  const std::string directory = scratch("latin");
  std::filesystem::create_directories(directory);
  const std::string file = directory + "/latin.yaml";
  auto plan_with_seed = [&](int seed) {
    std::ofstream(file) << "base: " << source_path("cases/c2_prescribed_heave/h0_passive.yaml") << "\n"
                        << "sampling: latin_hypercube\nsamples: 20\nseed: " << seed << "\n"
                        << "variables:\n  - {path: parameters.Z, sample: {from: 0.5, to: 1.5}}\n"
                        << "  - {path: parameters.T, sample: {from: 6, to: 16}}\n";
    return make_plan(read_sweep_file(file));
  };
  const SweepPlan plan = plan_with_seed(7);
  ASSERT_EQ(plan.runs.size(), 20u);
  const double from[2] = {0.5, 6}, to[2] = {1.5, 16};
  for (int j = 0; j < 2; ++j) {
    std::set<int> strata;
    for (const PlannedRun& run : plan.runs) strata.insert(static_cast<int>(std::floor((run.values[j] - from[j]) / (to[j] - from[j]) * 20)));
    EXPECT_EQ(strata.size(), 20u) << "variable " << j;
    EXPECT_EQ(*strata.begin(), 0);
    EXPECT_EQ(*strata.rbegin(), 19);
  }
  EXPECT_EQ(plan_with_seed(7).runs[5].values, plan.runs[5].values);  // the seed fixes the plan
  EXPECT_NE(plan_with_seed(8).runs[5].values, plan.runs[5].values);
  EXPECT_EQ(plan.runs[5].overrides().size(), 2u);
}

TEST(Sweep, AWorkerKilledByASignalHasItsTaskRecordedAndIsReplaced) {
  const std::unique_ptr<TaskDistribution> pool = make_process_pool(2);
  TaskCallbacks callbacks;
  callbacks.run = [](int index, int) -> std::string {
    if (index == 3) std::raise(SIGKILL);  // as the OOM killer ends a process
    return "ran " + std::to_string(index);
  };
  callbacks.crashed = [](int index, int, int signal) { return "crashed " + std::to_string(index) + " " + std::to_string(signal); };
  std::vector<int> finished;
  callbacks.finished = [&](int index, const std::string&) { finished.push_back(index); };
  callbacks.stop_requested = [] { return false; };
  const auto records = pool->run(8, callbacks);
  ASSERT_EQ(records.size(), 8u);
  for (int i = 0; i < 8; ++i)
    EXPECT_EQ(records[i].value(), i == 3 ? "crashed 3 " + std::to_string(SIGKILL) : "ran " + std::to_string(i));
  EXPECT_EQ(finished.size(), 8u);
}

TEST(Sweep, RunRecordsSurviveTheirEncoding) {
  RunRecord record;
  record.status = run_status::numerical_failure;
  record.exit_code = 3;
  record.wall_time_s = 1.25;
  record.result_file = "runs/run_0001.h5";
  record.message = "heavesim: numerical failure, \"quoted\"";
  record.rank_or_worker = 2;
  record.summary = {{"a", 1.0}, {"b", std::nan("")}};
  record.statistics = {{"/x", "kurtosis", "-", {3.0, 2.5}}};
  const RunRecord back = decode(encode(record));
  EXPECT_EQ(back.status, record.status);
  EXPECT_EQ(back.exit_code, 3);
  EXPECT_EQ(back.wall_time_s, 1.25);
  EXPECT_EQ(back.message, record.message);
  EXPECT_EQ(back.rank_or_worker, 2);
  ASSERT_EQ(back.summary.size(), 2u);
  EXPECT_TRUE(std::isnan(back.summary[1].second));
  EXPECT_EQ(back.statistics[0].columns, (std::vector<double>{3.0, 2.5}));
}

// docs/sweeps.md documents exactly the keys the reader accepts, with their units and
// defaults (tables marked `<!-- sweep-keys: <section> -->`), in both directions.
TEST(Sweep, EveryKeyOfTheSweepFileIsDocumentedAndEveryDocumentedKeyAccepted) {
  const auto documented = testing::documented_keys("docs/sweeps.md", "<!-- sweep-keys: ");
  std::size_t keys = 0;
  for (const SchemaSection& section : sweep_schema()) {
    SCOPED_TRACE(std::string(section.name));
    const auto table = documented.find(std::string(section.name));
    ASSERT_NE(table, documented.end());
    EXPECT_EQ(table->second.size(), section.keys.size());
    for (const KeySpec& spec : section.keys) {
      const auto key = table->second.find(std::string(spec.key));
      ASSERT_NE(key, table->second.end()) << spec.key;
      EXPECT_EQ(key->second.unit, spec.unit) << spec.key;
      EXPECT_EQ(key->second.default_value, spec.default_value) << spec.key;
      ++keys;
    }
  }
  EXPECT_EQ(documented.size(), sweep_schema().size());
  EXPECT_EQ(keys, 22u);
}

}  // namespace
}  // namespace heavesim
