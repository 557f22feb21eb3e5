// The result-file contract (docs/result-file.md): attributes, datasets with units and
// descriptions, the complete flag, partial files after a signal or a numerical failure.
#include <gtest/gtest.h>

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <future>
#include <map>
#include <sstream>
#include <string>
#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <vector>
#include <unistd.h>

#include "app/case/case_definition.hpp"
#include "app/output/recorder.hpp"
#include "app/output/result_file.hpp"
#include "app/scene/scene.hpp"
#include "kernel/algorithms/energy.hpp"
#include "kernel/algorithms/joint_reactions.hpp"
#include "kernel/math/numerical_error.hpp"
#include "tests/app/h5_file.hpp"
#include "tests/test_support.hpp"

extern char** environ;

namespace heavesim {
namespace {

TEST(ResultFile, CompleteRunFollowsTheContract) {
  const std::string output = temporary("two_link.h5"), csv_directory = temporary("csv");
  const testing::CommandResult result = testing::run_command_line(
      testing::heavesim_binary() + " run " + testing::source_path("cases/validation/two_link.yaml") + " -o " + output +
      " --csv " + csv_directory + " --set solver.t_end=1 --set output.interval=0.1");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  H5File file(output);
  ASSERT_TRUE(file.ok());
  for (const char* attribute : {"heavesim_version", "case_name", "case_sha256", "created_utc", "units_system"})
    EXPECT_TRUE(file.has_attribute("/", attribute)) << attribute;
  EXPECT_EQ(file.long_attribute("/", "complete"), 1);
  EXPECT_TRUE(file.exists("/case/yaml"));
  EXPECT_EQ(file.shape("/time"), std::vector<hsize_t>({11}));
  EXPECT_EQ(file.shape("/bodies/link1/position"), std::vector<hsize_t>({11, 3}));
  EXPECT_EQ(file.shape("/bodies/link1/orientation"), std::vector<hsize_t>({11, 4}));
  EXPECT_EQ(file.shape("/bodies/link1/velocity"), std::vector<hsize_t>({11, 6}));
  EXPECT_EQ(file.shape("/joints/elbow/q"), std::vector<hsize_t>({11, 1}));
  EXPECT_EQ(file.shape("/joints/elbow/reaction_force"), std::vector<hsize_t>({11, 3}));
  EXPECT_EQ(file.shape("/joints/elbow/reaction_moment"), std::vector<hsize_t>({11, 3}));
  for (const char* dataset : {"/time", "/joints/shoulder/reaction_force", "/signals/total_energy", "/case/yaml"}) {
    EXPECT_TRUE(file.has_attribute(dataset, "units")) << dataset;
    EXPECT_TRUE(file.has_attribute(dataset, "description")) << dataset;
  }
  // At release from rest the shoulder carries the full weight minus what the falling links take.
  const std::vector<double> time = file.read("/time");
  EXPECT_DOUBLE_EQ(time.back(), 1.0);
  const std::vector<double> q = file.read("/joints/shoulder/q");
  EXPECT_DOUBLE_EQ(q.front(), std::acos(0.0));
  // The whole-record statistics written at the end (through the series' open dataset,
  // over the NaN placeholders written at its creation) are those of the samples read back.
  const auto [q_min, q_max] = std::minmax_element(q.begin(), q.end());
  EXPECT_EQ(file.double_attribute("/joints/shoulder/q", "minimum"), *q_min);
  EXPECT_EQ(file.double_attribute("/joints/shoulder/q", "maximum"), *q_max);
  double q_sum = 0.0;
  for (double value : q) q_sum += value;
  EXPECT_NEAR(file.double_attribute("/joints/shoulder/q", "mean"), q_sum / q.size(), 1e-14);
  EXPECT_EQ(file.double_attribute("/time", "maximum"), 1.0);
  EXPECT_TRUE(std::filesystem::exists(csv_directory + "/two_link.csv"));
  std::ifstream csv(csv_directory + "/two_link.csv");
  std::string header;
  std::getline(csv, header);
  // Every column "<dataset><column label> [<unit>]" carries the unit of the dataset's
  // `units` attribute (per column where that names several).
  EXPECT_EQ(header.substr(0, header.find(',')), "time [s]");
  EXPECT_NE(header.find(",joints/elbow/reaction_force.x [N],"), std::string::npos) << header;
  EXPECT_NE(header.find(",bodies/link1/velocity.wz [rad/s],bodies/link1/velocity.vx [m/s],"), std::string::npos)
      << header;
  std::stringstream fields(header);
  int checked = 0;
  for (std::string field; std::getline(fields, field, ',');) {
    const std::size_t bracket = field.find(" [");
    ASSERT_NE(bracket, std::string::npos) << field;
    ASSERT_EQ(field.back(), ']') << field;
    const std::string name = field.substr(0, bracket), unit = field.substr(bracket + 2, field.size() - bracket - 3);
    const std::string dataset = "/" + name.substr(0, name.find_first_of(".["));
    ASSERT_TRUE(file.exists(dataset)) << field;
    const std::string units = file.string_attribute(dataset, "units");
    if (units.find(',') != std::string::npos) continue;  // several units: per column, checked above
    EXPECT_EQ(unit, units) << field;
    ++checked;
  }
  EXPECT_GT(checked, 20);
  std::filesystem::remove(output);
  std::filesystem::remove_all(csv_directory);
}

// The recorder writes a sample's values side by side into the file's staged row, a force
// element's outputs straight from outputs(). Checked against the elements' own outputs on a
// second build of the scene, evaluated apart at the same states, and the CSV column for
// column against the file (%.17g reads back to the same double). 4400 samples: past the
// staged runs of 64 and four blocks of 1024 (their hand-overs to the writer and the
// statistics), recorded in line and, on a build of their own, on the evaluation thread,
// alone or helped by the caller on a third build (the batches filled while the thread is
// busy, which lays the file out first: there the caller evaluates whole batches and fills
// the next; alone, every batch is full before the layout ends and waits, as record() only
// copies states: the 4,400 copies take well under a millisecond, the layout several).
bool same_recorded_number(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

enum class SampleEvaluation { in_line, second_thread, second_thread_and_caller };

/// Sample k at t = 1 ms k: the scene's initial state scaled by 1 + 1e-5 k and moved by up to
/// 5 cm (or 0.05 of a velocity's or an element state's unit) on a wave of a different phase
/// in every coordinate (the joints normalize quaternions): strokes, heights and loads that
/// vary from sample to sample, for the summary's figures.
void moving_states(const Scene& scene, int samples, std::vector<double>& times, std::vector<VectorX>& states) {
  for (int k = 0; k < samples; ++k) {
    times.push_back(1e-3 * k);
    VectorX state = scene.initial_state * (1.0 + 1e-5 * k);
    for (Eigen::Index j = 0; j < state.size(); ++j) state[j] += 0.05 * std::sin(0.037 * k + 0.7 * j);
    states.push_back(state);
  }
}

/// Every numeric attribute of the file's /summary (the compensators', the joint loads', the
/// energy's), read as double.
std::map<std::string, double> summary_numbers(const std::string& path) {
  std::map<std::string, double> numbers;
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t summary = H5Gopen2(file, "/summary", H5P_DEFAULT);
  H5Aiterate2(summary, H5_INDEX_NAME, H5_ITER_INC, nullptr,
              [](hid_t object, const char* name, const H5A_info_t*, void* found) -> herr_t {
                const hid_t attribute = H5Aopen(object, name, H5P_DEFAULT);
                const hid_t type = H5Aget_type(attribute);
                const H5T_class_t type_class = H5Tget_class(type);
                double value = 0.0;
                if ((type_class == H5T_FLOAT || type_class == H5T_INTEGER) &&
                    H5Aread(attribute, H5T_NATIVE_DOUBLE, &value) >= 0)
                  (*static_cast<std::map<std::string, double>*>(found))[name] = value;
                H5Tclose(type);
                H5Aclose(attribute);
                return 0;
              },
              &numbers);
  H5Gclose(summary);
  H5Fclose(file);
  return numbers;
}

/// Checks the recorded channels and CSV; returns the file's /summary numbers.
std::map<std::string, double> expect_recorded_element_outputs_and_csv(SampleEvaluation evaluation) {
  SCOPED_TRACE(evaluation == SampleEvaluation::in_line         ? "samples evaluated in line"
               : evaluation == SampleEvaluation::second_thread ? "samples evaluated on the second thread"
                                                               : "samples evaluated on the second thread and the caller's");
  const CaseDefinition definition =
      load_case(testing::source_path("cases/drilling.yaml"), {"solver.t_end=2", "output.evaluate_after=0"});
  Scene scene = build_scene(definition);
  Scene reference = build_scene(definition);
  Scene callers = build_scene(definition);
  constexpr int samples = 4400;  // more than the recorder's eight batches of 256 hold
  std::vector<double> times;
  std::vector<VectorX> states;
  moving_states(scene, samples, times, states);
  const std::string output = temporary("element_channels.h5"), csv_path = temporary("element_channels.csv");
  {
    ResultFile file(output, times.size());
    CsvWriter csv(csv_path);
    Recorder recorder(definition, scene, file, &csv);
    EXPECT_TRUE(recorder.needs_reactions());
    if (evaluation == SampleEvaluation::second_thread) recorder.evaluate_on_second_thread();
    if (evaluation == SampleEvaluation::second_thread_and_caller) recorder.evaluate_on_second_thread(&callers);
    for (std::size_t k = 0; k < times.size(); ++k) recorder.record(times[k], states[k]);
    recorder.record_queued_samples();
    EXPECT_EQ(recorder.samples(), samples);
    if (evaluation == SampleEvaluation::second_thread_and_caller) {
      EXPECT_GT(recorder.samples_evaluated_by_caller(), 0);
    } else {
      EXPECT_EQ(recorder.samples_evaluated_by_caller(), 0);
    }
    recorder.finish();
    file.mark_complete();
    file.close();
    csv.close();
  }
  const std::map<std::string, double> summary = summary_numbers(output);
  H5File file(output);
  EXPECT_TRUE(file.ok());
  if (!file.ok()) return summary;
  MultibodySystem& system = *reference.system;
  std::map<std::string, std::vector<double>> series;
  int element_channels = 0, mismatches = 0;
  for (std::size_t k = 0; k < times.size(); ++k) {
    system.evaluate(times[k], states[k], true);
    for (std::size_t e = 0; e < system.force_elements().size(); ++e) {
      const ForceElement& element = *system.force_elements()[e];
      std::vector<double> values(element.channels().size());
      element.outputs(times[k], system.model(), system.data(),
                      states[k].segment(system.state_offset(e), element.state_size()), values);
      for (std::size_t c = 0; c < values.size(); ++c) {
        const std::string dataset = "/forces/" + element.name() + "/" + element.channels()[c].name;
        if (!series.count(dataset)) {
          EXPECT_TRUE(file.exists(dataset)) << dataset;
          if (!file.exists(dataset)) return summary;
          series[dataset] = file.read(dataset);
        }
        if (!same_recorded_number(series[dataset].at(k), values[c]) && ++mismatches <= 5)
          ADD_FAILURE() << dataset << " at t = " << times[k] << ": " << series[dataset][k] << " recorded, "
                        << values[c] << " from the element";
        if (k == 0) ++element_channels;
      }
    }
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(element_channels, 40);  // the rig's compensators and hydrodynamic loads

  // The other channels (a fill each) against the reference scene's own stages.
  const Model& model = system.model();
  int checked = 0;
  auto expect_recorded = [&](const std::string& dataset, std::size_t k, const VectorX& expected) {
    if (!series.count(dataset)) {
      ASSERT_TRUE(file.exists(dataset)) << dataset;
      series[dataset] = file.read(dataset);
    }
    const std::vector<double>& numbers = series[dataset];
    ASSERT_EQ(numbers.size(), times.size() * expected.size()) << dataset;
    for (Eigen::Index c = 0; c < expected.size(); ++c)
      if (!same_recorded_number(numbers[k * expected.size() + c], expected[c]) && ++mismatches <= 5)
        ADD_FAILURE() << dataset << "[" << c << "] at t = " << times[k] << ": " << numbers[k * expected.size() + c]
                      << " recorded, " << expected[c] << " expected";
    ++checked;
  };
  for (std::size_t k = 0; k < times.size(); ++k) {
    system.evaluate(times[k], states[k], true);
    expect_recorded("/time", k, VectorX::Constant(1, times[k]));
    for (int i = 1; i < model.num_links(); ++i) {
      const Joint& joint = model.joints[i];
      const std::string base = "/joints/" + joint.name;
      if (joint.nv > 0) {
        expect_recorded(base + "/q", k, states[k].segment(joint.q_index, joint.nq));
        expect_recorded(base + "/qd", k, states[k].segment(model.nq + joint.v_index, joint.nv));
        expect_recorded(base + "/qdd", k, system.data().qdd.segment(joint.v_index, joint.nv));
      }
      expect_recorded(base + "/reaction_force", k, joint_reaction(model, system.data(), i).force_world);
      expect_recorded("/bodies/" + model.links[i].name + "/position", k,
                      (system.data().X_world_link[i] * model.links[i].X_link_body).translation());
    }
    expect_recorded("/signals/kinetic_energy", k, VectorX::Constant(1, kinetic_energy(model, system.data())));
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(checked, 10 * static_cast<int>(times.size()));

  std::ifstream csv(csv_path);
  std::string header;
  std::getline(csv, header);
  std::vector<std::string> datasets;  // per CSV column
  std::stringstream fields(header);
  for (std::string field; std::getline(fields, field, ',');)
    datasets.push_back("/" + field.substr(0, field.find_first_of(".[ ")));
  for (const std::string& dataset : datasets)
    if (!series.count(dataset)) series[dataset] = file.read(dataset);
  std::size_t row = 0;
  mismatches = 0;
  for (std::string line; std::getline(csv, line); ++row) {
    std::stringstream values(line);
    std::size_t column = 0;
    std::string previous;
    std::size_t column_of_dataset = 0;
    for (std::string value; std::getline(values, value, ','); ++column) {
      EXPECT_LT(column, datasets.size());
      if (column >= datasets.size()) return summary;
      column_of_dataset = datasets[column] == previous ? column_of_dataset + 1 : 0;
      previous = datasets[column];
      const std::vector<double>& numbers = series.at(datasets[column]);
      const std::size_t width = numbers.size() / times.size();
      if (!same_recorded_number(std::strtod(value.c_str(), nullptr), numbers.at(row * width + column_of_dataset)) &&
          ++mismatches <= 5)
        ADD_FAILURE() << datasets[column] << " column " << column_of_dataset << " row " << row << ": " << value;
    }
    EXPECT_EQ(column, datasets.size());
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_EQ(row, times.size());
  std::filesystem::remove(output);
  std::filesystem::remove(csv_path);
  return summary;
}

TEST(Recorder, ElementChannelsHoldTheElementsOutputsAndTheCsvTheFilesNumbers) {
  const std::map<std::string, double> in_line = expect_recorded_element_outputs_and_csv(SampleEvaluation::in_line);
  // The compensators' figures (strokes, pressures, efficiency), the joint loads and the
  // energy change, taken in sample order from values measured on whichever scene
  // evaluated the sample: the same numbers as in line.
  EXPECT_GT(in_line.count("passive_stroke_max_m"), 0u);
  EXPECT_GT(in_line.count("active_force_max_abs_N"), 0u);
  EXPECT_GT(in_line.count("relative_energy_change"), 0u);
  EXPECT_GT(in_line.size(), 20u);
  for (const SampleEvaluation beside : {SampleEvaluation::second_thread, SampleEvaluation::second_thread_and_caller}) {
    const std::map<std::string, double> summary = expect_recorded_element_outputs_and_csv(beside);
    EXPECT_EQ(summary.size(), in_line.size());
    for (const auto& [name, value] : in_line)
      EXPECT_TRUE(summary.count(name) && same_recorded_number(summary.at(name), value))
          << name << ": " << value << " in line, " << (summary.count(name) ? summary.at(name) : std::nan(""));
  }
}

// A sample whose evaluation fails (a speed that is not a number: no finite acceleration)
// ends the record there, the samples before it in the file and none after, whichever
// thread evaluated it: in line, the evaluation thread, or the caller on its own scene
// (sample 259 is the fourth of the second batch, which the caller starts while the thread
// is on the first). The failure is thrown by a later record() or record_queued_samples().
TEST(Recorder, ASampleThatFailsEndsTheRecordWhereverItWasEvaluated) {
  const CaseDefinition definition =
      load_case(testing::source_path("cases/drilling.yaml"), {"solver.t_end=2", "output.evaluate_after=0"});
  Scene scene = build_scene(definition);
  Scene callers = build_scene(definition);
  constexpr int samples = 1100, failing = 259;
  std::vector<double> times;
  std::vector<VectorX> states;
  moving_states(scene, samples, times, states);
  states[failing][scene.model->nq] = std::nan("");  // the first speed
  for (const SampleEvaluation evaluation :
       {SampleEvaluation::in_line, SampleEvaluation::second_thread, SampleEvaluation::second_thread_and_caller}) {
    SCOPED_TRACE(static_cast<int>(evaluation));
    const std::string output = temporary("failing_sample.h5");
    ResultFile file(output, times.size());
    Recorder recorder(definition, scene, file, nullptr);
    if (evaluation == SampleEvaluation::second_thread) recorder.evaluate_on_second_thread();
    if (evaluation == SampleEvaluation::second_thread_and_caller) recorder.evaluate_on_second_thread(&callers);
    double failed_at = -1.0;
    try {
      for (std::size_t k = 0; k < times.size(); ++k) recorder.record(times[k], states[k]);
      recorder.record_queued_samples();
    } catch (const NumericalError& error) {
      failed_at = error.time();
    }
    EXPECT_EQ(failed_at, times[failing]);
    EXPECT_EQ(recorder.samples(), failing);
    EXPECT_EQ(recorder.last_sample_time(), times[failing - 1]);
    if (evaluation == SampleEvaluation::second_thread_and_caller) {
      EXPECT_GT(recorder.samples_evaluated_by_caller(), 0);
    }
    recorder.record_queued_samples();  // nothing more: the samples after the failure were dropped
    EXPECT_EQ(recorder.samples(), failing);
    file.close();
    std::filesystem::remove(output);
  }
}

TEST(ResultFile, SignalStopsTheRunAndLeavesAReadableIncompleteFile) {
  const std::string output = temporary("long_run.h5");
  const std::string binary = testing::heavesim_binary(), case_path = testing::source_path("tests/cases/long_run.yaml");
  std::vector<char*> argv = {const_cast<char*>(binary.c_str()), const_cast<char*>("run"),
                             const_cast<char*>(case_path.c_str()), const_cast<char*>("-o"),
                             const_cast<char*>(output.c_str()), const_cast<char*>("--quiet"), nullptr};
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, binary.c_str(), nullptr, nullptr, argv.data(), environ), 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  H5File file(output);
  ASSERT_TRUE(file.ok());
  EXPECT_EQ(file.long_attribute("/", "complete"), 0);
  const std::vector<double> time = file.read("/time");
  ASSERT_GT(time.size(), 1u);
  EXPECT_LT(time.back(), 1000.0);
  EXPECT_EQ(file.shape("/joints/pivot/reaction_force")[0], time.size());
  std::filesystem::remove(output);
}

TEST(ResultFile, AKilledWriterLeavesWholeSamples) {
  // A child process writes samples as the recorder does and is killed (SIGKILL: no
  // handler, no clean-up) in the middle of a sample, just after the first series of the
  // 2048th sample (two chunks' worth) was appended. Whatever reached the disk must be
  // whole samples: every series as long as /time, /time in order.
  const std::string output = temporary("killed_writer.h5");
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    try {
      ResultFile file(output);
      const int time = file.add_series("/time", 0, "s", "time");
      const int position = file.add_series("/bodies/b/position", 3, "m", "position");
      const int energy = file.add_series("/signals/energy", 0, "J", "energy");
      file.flush();  // the metadata, as a run writes it before its first step
      for (int k = 0; k < 2048; ++k) {
        const double t = k, xyz[3] = {k + 0.1, k + 0.2, k + 0.3}, e = 2.0 * k;
        file.append(time, &t);
        if (k == 2047) kill(getpid(), SIGKILL);
        file.append(position, xyz);
        file.append(energy, &e);
        file.end_sample();
      }
    } catch (...) {
    }
    _exit(2);  // not reached unless the writer threw
  }
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "the writer was not killed";
  H5File file(output);
  ASSERT_TRUE(file.ok());
  const std::vector<double> time = file.read("/time");
  ASSERT_EQ(time.size(), 1024u);  // the first chunk of samples, nothing of the second
  EXPECT_EQ(file.shape("/bodies/b/position")[0], time.size());
  EXPECT_EQ(file.shape("/signals/energy")[0], time.size());
  for (std::size_t k = 0; k < time.size(); ++k) ASSERT_EQ(time[k], static_cast<double>(k));
  std::filesystem::remove(output);
}

/// Reads back every series "/series_<s>" of `output` (widths[s] columns, 0 for a
/// one-dimensional series): `samples` rows, value(k, s, c) in row k, column c.
template <class Value>
void expect_series_read_back(const std::string& output, const std::vector<int>& widths, long samples,
                             const Value& value) {
  const H5File file(output);
  ASSERT_TRUE(file.ok());
  for (std::size_t s = 0; s < widths.size(); ++s) {
    const std::vector<double> values = file.read("/series_" + std::to_string(s));
    const int width = std::max(widths[s], 1);
    ASSERT_EQ(values.size(), static_cast<std::size_t>(samples * width)) << "series " << s;
    for (long k = 0; k < samples; ++k)
      for (int c = 0; c < width; ++c)
        ASSERT_EQ(values[k * width + c], value(k, static_cast<int>(s), c))
            << "series " << s << " sample " << k << " column " << c;
  }
}

TEST(ResultFile, EverySampleLandsInItsRowThroughRunsBlocksAndFlushes) {
  // Series of widths 1, 3 and 7 (rows staged side by side, then moved to each series'
  // block a run of 64 samples at a time, result_file.hpp), 4000 samples: whole blocks of
  // 1024 handed to the block writer (after k = 1124, 2523, 3547), flushes off the runs'
  // and blocks' boundaries, one between the appends of a sample (whose first row must
  // survive it), and a read of the block being built (block(), which moves a run short
  // of 64) before the next block ends. Value (k, series s, column c) = 1000 k + 10 s + c,
  // read back from the block and from the file. 1024 samples reserved: the chunk index's
  // nodes hold two chunks (K = 1, app/output/result_file.cpp), so the four blocks make
  // HDF5 split them.
  const std::string output = temporary("rows.h5");
  const int widths[3] = {0, 3, 7};
  const long samples = 4000;
  const auto value = [](long k, int s, int c) { return 1000.0 * k + 10.0 * s + c; };
  {
    ResultFile file(output, 1024);
    int ids[3];
    for (int s = 0; s < 3; ++s)
      ids[s] = file.add_series("/series_" + std::to_string(s), widths[s], "-", "test pattern");
    file.flush();
    std::vector<double> row(7);
    for (long k = 0; k < samples; ++k) {
      for (int s = 0; s < 3; ++s) {
        for (int c = 0; c < std::max(widths[s], 1); ++c) row[c] = value(k, s, c);
        file.append(ids[s], row.data());
        if (k == 1500 && s == 0) file.flush();  // between the appends of a sample
      }
      file.end_sample();
      if (k == 100 || k == 1300 || k == 3900) file.flush();
      if (k == 1600 || k == 1637) {
        // The block being built holds samples k - buffered + 1 .. k, in order.
        const long buffered = static_cast<long>(file.buffered_samples());
        ASSERT_GT(buffered, 0);
        const double* block = file.block(ids[2]);
        for (long r = 0; r < buffered; ++r)
          for (int c = 0; c < 7; ++c)
            ASSERT_EQ(block[r * 7 + c], value(k - buffered + 1 + r, 2, c)) << "sample " << k << " row " << r;
      }
    }
    file.close();
  }
  expect_series_read_back(output, {widths, widths + 3}, samples, value);
  std::filesystem::remove(output);
}

// A whole block goes to disk as its chunks, raw, over the places allocated for them at the
// layout, which lays each block's chunks side by side in the order of the series (one
// pwrite for them all). The test reads back, through HDF5's own index (H5Dget_chunk_info
// on a second identifier of the open file), where every chunk is after the layout and
// after three whole blocks: the same places and sizes (nothing allocated or re-indexed
// while samples are written, the file's SIGKILL design, result_file.hpp), block k of the
// second series right after block k of the first, and the rows read back are the ones
// written (a chunk written past its end, or at another's place, would overwrite what was
// written there: the next chunk, or the series after).
TEST(ResultFile, WholeBlocksAreWrittenOverTheChunksTheLayoutAllocated) {
  const std::string output = temporary("chunks.h5");
  const int widths[2] = {0, 3};
  const long samples = 3 * static_cast<long>(ResultFile::block_rows);  // whole blocks only
  const auto value = [](long k, int s, int c) { return 0.5 * k - 7.0 * s + c; };
  std::vector<std::vector<H5File::ChunkPlace>> after_layout(2), after_samples(2);
  {
    ResultFile file(output, samples);
    int ids[2];
    for (int s = 0; s < 2; ++s)
      ids[s] = file.add_series("/series_" + std::to_string(s), widths[s], "-", "test pattern");
    file.flush();  // the layout on disk, published
    {
      const H5File reader(output);
      ASSERT_TRUE(reader.ok());
      for (int s = 0; s < 2; ++s) after_layout[s] = reader.chunk_places("/series_" + std::to_string(s));
    }
    double row[3];
    for (long k = 0; k < samples; ++k) {
      for (int s = 0; s < 2; ++s) {
        for (int c = 0; c < std::max(widths[s], 1); ++c) row[c] = value(k, s, c);
        file.append(ids[s], row);
      }
      file.end_sample();
    }
    file.flush();
    {
      const H5File reader(output);
      ASSERT_TRUE(reader.ok());
      for (int s = 0; s < 2; ++s) after_samples[s] = reader.chunk_places("/series_" + std::to_string(s));
    }
    file.close();
  }
  for (int s = 0; s < 2; ++s) {
    const std::size_t width = static_cast<std::size_t>(std::max(widths[s], 1));
    ASSERT_EQ(after_layout[s].size(), 3u) << "series " << s << ": a chunk for each block, allocated at the layout";
    EXPECT_EQ(after_samples[s], after_layout[s]) << "series " << s;
    for (const H5File::ChunkPlace& place : after_layout[s])
      EXPECT_EQ(place.bytes, ResultFile::block_rows * width * sizeof(double)) << "series " << s;
  }
  for (std::size_t k = 0; k < after_layout[0].size() && k < after_layout[1].size(); ++k) {
    ASSERT_EQ(after_layout[0][k].first_row, after_layout[1][k].first_row) << "chunk " << k;
    EXPECT_EQ(after_layout[1][k].address, after_layout[0][k].address + after_layout[0][k].bytes)
        << "block " << k << ": the second series' chunk does not follow the first's";
  }
  expect_series_read_back(output, {widths, widths + 2}, samples, value);
  std::filesystem::remove(output);
}

// A record attribute (a compound of doubles, as a channel's statistics) written at the
// layout and again at the end: with the same fields it is overwritten in place; with
// fields of the same count and size but another name it must be written anew, names and
// values, not reinterpreted (result_file.cpp compares the stored type member by member).
TEST(ResultFile, RecordAttributeKeepsItsFieldsWhenOverwritten) {
  const std::string output = temporary("records.h5");
  const double nan = std::nan("");
  {
    ResultFile file(output);
    const int id = file.add_series("/series", 2, "-", "two columns");
    file.set_record_attribute(id, "statistics", {"mean", "std"}, {nan, nan, nan, nan});
    file.set_record_attribute(id, "other", {"a", "b"}, {nan, nan});
    file.flush();  // published: headers no longer grow
    file.set_record_attribute(id, "statistics", {"mean", "std"}, {1.0, 2.0, 3.0, 4.0});
    // Other fields: deleted and made again, the series' other attributes closed first.
    file.set_record_attribute(id, "other", {"a", "c"}, {5.0, 6.0});
    // Opened again when written, then written through the handle kept open.
    file.set_record_attribute(id, "statistics", {"mean", "std"}, {7.0, 8.0, 9.0, 10.0});
    file.set_record_attribute(id, "statistics", {"mean", "std"}, {11.0, 12.0, 13.0, 14.0});
    file.close();
  }
  const auto read_records = [&](const std::string& name, std::vector<std::string>& fields) {
    const hid_t file = H5Fopen(output.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const hid_t attribute = H5Aopen_by_name(file, "/series", name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    const hid_t type = H5Aget_type(attribute), space = H5Aget_space(attribute);
    fields.clear();
    for (int m = 0; m < H5Tget_nmembers(type); ++m) {
      char* field = H5Tget_member_name(type, static_cast<unsigned>(m));
      fields.emplace_back(field);
      H5free_memory(field);
    }
    std::vector<double> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)) * fields.size());
    EXPECT_GE(H5Aread(attribute, type, values.data()), 0);
    H5Sclose(space), H5Tclose(type), H5Aclose(attribute), H5Fclose(file);
    return values;
  };
  std::vector<std::string> fields;
  EXPECT_EQ(read_records("statistics", fields), (std::vector<double>{11.0, 12.0, 13.0, 14.0}));
  EXPECT_EQ(fields, (std::vector<std::string>{"mean", "std"}));
  EXPECT_EQ(read_records("other", fields), (std::vector<double>{5.0, 6.0}));
  EXPECT_EQ(fields, (std::vector<std::string>{"a", "c"}));
  std::filesystem::remove(output);
}

// What the layout stores once or not at all (docs/performance.md, "Issue #18,
// twenty-third round"): the chunk index's nodes sized to the reservation (5,000 samples:
// five chunks a series, held by one node of K = 3), the record type a datatype object that
// every series' record refers to, and no modification time in the series' headers (two
// runs of a case give files that differ in their timings only).
TEST(ResultFile, TheLayoutSizesTheChunkIndexAndStoresTheRecordTypeOnce) {
  const std::string output = temporary("layout.h5");
  const double nan = std::nan("");
  {
    ResultFile file(output, 5000);
    const int scalar = file.add_series("/scalar", 0, "-", "one column");
    const int triple = file.add_series("/triple", 3, "-", "three columns");
    file.set_record_attribute(scalar, "statistics", {"mean", "std"}, {nan, nan});
    file.set_record_attribute(triple, "statistics", {"mean", "std"}, std::vector<double>(6, nan));
    file.flush();
    file.set_record_attribute(triple, "statistics", {"mean", "std"}, {1.0, 2.0, 3.0, 4.0, 5.0, 6.0});
    file.close();
    // Ended by close(), while the ResultFile lives on: were a stored type still open, HDF5
    // would keep the file open for writing (and end it only once the type closes), and an
    // open of the path would share that file, writable.
    const hid_t reopened = H5Fopen(output.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    unsigned intent = 0;
    EXPECT_GE(H5Fget_intent(reopened, &intent), 0);
    EXPECT_EQ(intent, H5F_ACC_RDONLY);
    H5Fclose(reopened);
  }
  const hid_t file = H5Fopen(output.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const hid_t creation = H5Fget_create_plist(file);
  unsigned k = 0;
  EXPECT_GE(H5Pget_istore_k(creation, &k), 0);
  EXPECT_EQ(k, 3u);
  H5Pclose(creation);
  haddr_t record_type_address[2] = {HADDR_UNDEF, HADDR_UNDEF};
  const char* series[2] = {"/scalar", "/triple"};
  for (int s = 0; s < 2; ++s) {
    H5O_info_t dataset{};
    EXPECT_GE(H5Oget_info_by_name2(file, series[s], &dataset, H5O_INFO_BASIC | H5O_INFO_TIME, H5P_DEFAULT), 0);
    EXPECT_EQ(dataset.mtime, 0) << series[s];
    EXPECT_EQ(dataset.ctime, 0) << series[s];
    const hid_t attribute = H5Aopen_by_name(file, series[s], "statistics", H5P_DEFAULT, H5P_DEFAULT);
    const hid_t type = H5Aget_type(attribute);
    EXPECT_GT(H5Tcommitted(type), 0) << series[s];
    H5O_info_t shared{};
    EXPECT_GE(H5Oget_info2(type, &shared, H5O_INFO_BASIC), 0);
    record_type_address[s] = shared.addr;
    if (s == 1) {
      std::vector<double> values(6);
      EXPECT_GE(H5Aread(attribute, type, values.data()), 0);
      EXPECT_EQ(values, (std::vector<double>{1.0, 2.0, 3.0, 4.0, 5.0, 6.0}));
    }
    H5Tclose(type), H5Aclose(attribute);
  }
  EXPECT_NE(record_type_address[0], HADDR_UNDEF);
  EXPECT_EQ(record_type_address[0], record_type_address[1]);
  H5Fclose(file);
  std::filesystem::remove(output);
}

// An earlier file at the path goes at once (a stale complete = 1 must not stand for a run
// that then fails in its set-up): a regular file by its name, its pages freed by a helper
// thread (result_file.cpp); a FIFO removed, never opened (an open for reading would wait for
// a writer); a link removed, not its target.
TEST(ResultFile, AnEarlierFileAtThePathIsRemovedAtOnce) {
  const std::string output = temporary("replaced.h5"), target = temporary("replaced_link_target.txt");
  const auto gone = [&] { return !std::filesystem::exists(std::filesystem::symlink_status(output)); };
  std::filesystem::remove(output);
  std::ofstream(output) << std::string(std::size_t{1} << 22, 'x');  // 4 MiB: pages to free
  {
    ResultFile file(output);
    EXPECT_TRUE(gone());  // the new file takes the name at its first flush
    file.add_series("/series", 0, "-", "one column");
    file.close();
  }
  EXPECT_GT(H5Fis_hdf5(output.c_str()), 0);
  // The replaced file was held open while its name went; it is closed (its pages freed) by
  // the time the result file is: no descriptor of this process still names it.
  for (const auto& descriptor : std::filesystem::directory_iterator("/proc/self/fd")) {
    std::error_code unreadable;  // the iterator's own descriptor, closed by the time it is read
    const std::string names = std::filesystem::read_symlink(descriptor.path(), unreadable).string();
    EXPECT_EQ(names.find("replaced.h5 (deleted)"), std::string::npos) << descriptor.path() << " -> " << names;
  }
  std::filesystem::remove(output);

  ASSERT_EQ(mkfifo(output.c_str(), 0600), 0);
  std::future<bool> fifo_removed = std::async(std::launch::async, [&] {
    ResultFile file(output);
    return gone();
  });
  if (fifo_removed.wait_for(std::chrono::seconds(20)) == std::future_status::timeout) {
    ADD_FAILURE() << "the result file's constructor waits on the FIFO at its path";
    const int writer = ::open(output.c_str(), O_WRONLY | O_NONBLOCK);  // lets a waiting open return
    if (writer >= 0) ::close(writer);
  }
  EXPECT_TRUE(fifo_removed.get());

  std::ofstream(target) << "kept";
  std::filesystem::create_symlink(target, output);
  {
    ResultFile file(output);
    EXPECT_TRUE(gone());
  }
  EXPECT_TRUE(std::filesystem::exists(target));
  std::filesystem::remove(target);
}

// A record's fields are stored in name order, each at its place in the row: the stored
// members are sorted by name, and a read with a memory type built here in the writer's
// order (HDF5 matches members by name and offset) puts every value back in its field, so
// a field stored at its place in name order instead (a wrong offset) fails.
TEST(ResultFile, RecordFieldsAreStoredInNameOrderAndReadBackByName) {
  const std::string output = temporary("records_by_name.h5");
  const std::vector<std::string> fields = {"window_mean", "kurtosis", "mpm_rayleigh", "cycles"};
  {
    ResultFile file(output);
    const int id = file.add_series("/series", 2, "-", "two columns");
    file.set_record_attribute(id, "statistics", fields, std::vector<double>(8, std::nan("")));
    file.flush();  // published: overwritten in place below
    file.set_record_attribute(id, "statistics", fields, {1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0});
    file.close();
  }
  const hid_t file = H5Fopen(output.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t attribute = H5Aopen_by_name(file, "/series", "statistics", H5P_DEFAULT, H5P_DEFAULT);
  const hid_t stored = H5Aget_type(attribute);
  std::vector<std::string> stored_names;
  for (int m = 0; m < H5Tget_nmembers(stored); ++m) {
    char* name = H5Tget_member_name(stored, static_cast<unsigned>(m));
    stored_names.emplace_back(name);
    H5free_memory(name);
  }
  EXPECT_EQ(stored_names, (std::vector<std::string>{"cycles", "kurtosis", "mpm_rayleigh", "window_mean"}));
  const hid_t memory = H5Tcreate(H5T_COMPOUND, fields.size() * sizeof(double));
  for (std::size_t f = 0; f < fields.size(); ++f)
    H5Tinsert(memory, fields[f].c_str(), f * sizeof(double), H5T_NATIVE_DOUBLE);
  std::vector<double> values(8, 0.0);
  EXPECT_GE(H5Aread(attribute, memory, values.data()), 0);
  EXPECT_EQ(values, (std::vector<double>{1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0}));
  H5Tclose(memory), H5Tclose(stored), H5Aclose(attribute), H5Fclose(file);
  std::filesystem::remove(output);
}

// The whole record's minimum, maximum, mean and standard deviation are the samples before
// the evaluation window merged with the window's (each sample's moments taken once): over
// three blocks of 1024 samples with the window starting inside the second, they are those
// of every sample read back (extremes exactly; mean and sample standard deviation to
// round-off), for a scalar-per-row and a three-column series.
TEST(ResultFile, WholeRecordStatisticsSpanTheEvaluationWindowsStart) {
  const std::string output = temporary("window_spanning.h5");
  const testing::CommandResult result = testing::run_command_line(
      testing::heavesim_binary() + " run " + testing::source_path("cases/validation/two_link.yaml") + " -o " + output +
      " -q --set solver.t_end=3 --set output.interval=0.001 --set output.evaluate_after=1.2345");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  H5File file(output);
  ASSERT_TRUE(file.ok());
  for (const auto& [dataset, columns] : {std::pair{"/joints/shoulder/q", 1}, std::pair{"/joints/elbow/reaction_force", 3}}) {
    const std::vector<double> values = file.read(dataset);
    const std::size_t rows = values.size() / columns;
    ASSERT_EQ(rows, 3001u) << dataset;
    const std::vector<double> minimum = file.double_attributes(dataset, "minimum");
    const std::vector<double> maximum = file.double_attributes(dataset, "maximum");
    const std::vector<double> mean = file.double_attributes(dataset, "mean");
    const std::vector<double> deviation = file.double_attributes(dataset, "standard_deviation");
    for (const std::vector<double>* attribute : {&minimum, &maximum, &mean, &deviation})
      ASSERT_EQ(attribute->size(), static_cast<std::size_t>(columns)) << dataset;
    for (int c = 0; c < columns; ++c) {
      double low = values[c], high = values[c], sum = 0.0;
      for (std::size_t r = 0; r < rows; ++r) {
        low = std::min(low, values[r * columns + c]);
        high = std::max(high, values[r * columns + c]);
        sum += values[r * columns + c];
      }
      const double average = sum / rows;
      double squares = 0.0;
      for (std::size_t r = 0; r < rows; ++r) squares += std::pow(values[r * columns + c] - average, 2);
      const double sample_deviation = std::sqrt(squares / (rows - 1.0));
      EXPECT_EQ(minimum[c], low) << dataset << " column " << c;
      EXPECT_EQ(maximum[c], high) << dataset << " column " << c;
      // Round-off of sums over 3001 values of size |x|max: a few 1e-16 |x|max * sqrt(n).
      const double scale = std::max(std::abs(low), std::abs(high));
      EXPECT_NEAR(mean[c], average, 1e-13 * scale) << dataset << " column " << c;
      EXPECT_NEAR(deviation[c], sample_deviation, 1e-13 * scale) << dataset << " column " << c;
    }
  }
  std::filesystem::remove(output);
}

TEST(ResultFile, NumericalFailureExitsWithCodeThreeAndADiagnosis) {
  const std::string output = temporary("unstable.h5");
  const testing::CommandResult result = testing::run_command_line(
      testing::heavesim_binary() + " run " + testing::source_path("tests/cases/unstable_spring.yaml") + " -o " + output);
  EXPECT_EQ(result.exit_code, 3) << result.output;
  EXPECT_NE(result.output.find("joint 'slide'"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("suggestion"), std::string::npos) << result.output;
  H5File file(output);
  ASSERT_TRUE(file.ok());
  EXPECT_EQ(file.long_attribute("/", "complete"), 0);
  EXPECT_TRUE(file.has_attribute("/", "failure"));
  EXPECT_TRUE(file.has_attribute("/", "failure_time"));
  // Everything recorded before the failure is finite: no silent NaN in the file.
  for (double value : file.read("/joints/slide/q")) EXPECT_TRUE(std::isfinite(value));
  std::filesystem::remove(output);
}

}  // namespace
}  // namespace heavesim
