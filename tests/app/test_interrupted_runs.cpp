// Runs that end in any way but a clean finish (docs/result-file.md, "Written as the run
// goes"): a writer killed (SIGKILL) at every one of its writes, real runs killed at
// random moments, and SIGTERM in the first milliseconds, before and while the case loads.
// The reader's rule under test: the file, when it exists, opens; every series has the
// same number of rows; the first `samples_written` rows are whole samples of the run.
#include <gtest/gtest.h>

#include <spawn.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <mutex>
#include <random>
#include <thread>
#include <utility>
#include <vector>

#include "app/output/result_file.hpp"
#include "tests/app/h5_file.hpp"
#include "tests/test_support.hpp"

extern char** environ;

// Every write to a result file goes through pwrite: HDF5's (its POSIX driver) and the
// result file's own raw chunk writes (ResultFile::write_raw). A process that arms this
// counter is killed at its n-th write from then on, exactly as SIGKILL would stop it
// between two system calls: the file then holds the first n - 1 writes and nothing else.
// A test that sets recorded_writes gets every write's (offset, bytes). Unarmed (the
// default, and every other test) it only forwards the call.
namespace {
long writes_before_kill = -1;
std::mutex recorded_writes_mutex;  // the block writer's thread writes too
std::vector<std::pair<off_t, size_t>>* recorded_writes = nullptr;
}  // namespace
extern "C" ssize_t pwrite(int descriptor, const void* buffer, size_t size, off_t offset) {
  if (writes_before_kill >= 0 && writes_before_kill-- == 0) kill(getpid(), SIGKILL);
  {
    const std::lock_guard lock(recorded_writes_mutex);
    if (recorded_writes != nullptr) recorded_writes->emplace_back(offset, size);
  }
  return syscall(SYS_pwrite64, descriptor, buffer, size, offset);
}

namespace heavesim {
namespace {

// The writer's samples: known values, so that a reader can tell a whole sample.
constexpr long writer_samples = 2600;  // two chunks of 1024 and a partial one
double time_of(long k) { return 0.5 * k; }
double energy_of(long k) { return 3.0 * k + 1.0; }

/// Writes a run as `heavesim run` does: layout, samples, statistics, summary, complete.
void write_run(const std::string& path) {
  ResultFile file(path, writer_samples);
  file.set_attribute("/", "complete", 0L);
  const int time = file.add_series("/time", 0, "s", "time");
  const int position = file.add_series("/bodies/b/position", 3, "m", "position");
  const int energy = file.add_series("/signals/energy", 0, "J", "energy");
  file.flush();
  for (long k = 0; k < writer_samples; ++k) {
    const double t = time_of(k), xyz[3] = {1.0 * k, -1.0 * k, 2.0 * k}, e = energy_of(k);
    file.append(time, &t);
    file.append(position, xyz);
    file.append(energy, &e);
    file.end_sample();
  }
  file.flush();
  // A value per series, so that a reader can tell a statistic written to the wrong series.
  for (const char* statistic : ResultFile::series_statistics) {
    file.set_attribute(time, statistic, {1.0});
    file.set_attribute(energy, statistic, {2.0});
  }
  file.set_attribute("/summary", "samples", writer_samples);
  file.set_attribute("/summary", "wall_time_s", 0.25);
  file.mark_complete();
  file.close();
}

/// Checks a file the writer left when killed; returns "" or what is wrong.
std::string whole_samples_problem(const std::string& path) {
  H5File file(path);
  if (!file.ok()) return "the file does not open";
  const long written = file.long_attribute("/", "samples_written");
  if (written < 0 || written > writer_samples) return "samples_written = " + std::to_string(written);
  const hsize_t rows = file.shape("/time")[0];
  for (const char* series : {"/bodies/b/position", "/signals/energy"})
    if (file.shape(series)[0] != rows) return std::string(series) + " has another length than /time";
  if (rows < static_cast<hsize_t>(written)) return "fewer rows than samples_written";
  const std::vector<double> time = file.read("/time"), position = file.read("/bodies/b/position"),
                            energy = file.read("/signals/energy");
  for (long k = 0; k < written; ++k)
    if (time[k] != time_of(k) || energy[k] != energy_of(k) || position[3 * k + 2] != 2.0 * k)
      return "sample " + std::to_string(k) + " is not the one written";
  const long complete = file.long_attribute("/", "complete");
  if (complete == 1 && written != writer_samples) return "complete = 1 before every sample was written";
  // The statistics are there at every point: "not computed" (NaN) or their value, each
  // on its own series.
  const double time_minimum = file.double_attribute("/time", "minimum");
  const double energy_minimum = file.double_attribute("/signals/energy", "minimum");
  if (!std::isnan(time_minimum) && time_minimum != 1.0) return "unreadable statistics of /time";
  if (!std::isnan(energy_minimum) && energy_minimum != 2.0) return "unreadable statistics of /signals/energy";
  if (complete == 1 && (time_minimum != 1.0 || energy_minimum != 2.0)) return "complete = 1 without the statistics";
  return "";
}

// The writer's three series (1 + 3 + 1 columns) lay each block's chunks side by side, so
// a block is ONE pwrite of 1024 x 5 doubles at the first series' chunk (not one a series,
// ResultFile::write_whole_block), the last, partial block (552 samples) too; and what was
// written reads back (whole_samples_problem). Fails if the raw path is not taken (the
// writes would be 8 kB, 24 kB, 8 kB) or the chunks are not adjacent.
TEST(ResultFileWrites, AWholeBlockIsOnePwriteOverItsSeriesChunksSideBySide) {
  const std::string path = temporary("one_write_a_block.h5");
  std::vector<std::pair<off_t, size_t>> writes;
  {
    const std::lock_guard lock(recorded_writes_mutex);
    recorded_writes = &writes;
  }
  write_run(path);
  {
    const std::lock_guard lock(recorded_writes_mutex);
    recorded_writes = nullptr;
  }
  EXPECT_EQ(whole_samples_problem(path), "");
  const H5File file(path);
  ASSERT_TRUE(file.ok());
  const std::vector<H5File::ChunkPlace> time = file.chunk_places("/time"),
                                        position = file.chunk_places("/bodies/b/position"),
                                        energy = file.chunk_places("/signals/energy");
  ASSERT_EQ(time.size(), 3u);
  ASSERT_EQ(position.size(), 3u);
  ASSERT_EQ(energy.size(), 3u);
  const size_t block_bytes = ResultFile::block_rows * 5 * sizeof(double);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(position[k].address, time[k].address + time[k].bytes) << "block " << k;
    EXPECT_EQ(energy[k].address, position[k].address + position[k].bytes) << "block " << k;
    long at_block = 0, at_a_series_chunk = 0;
    for (const auto& [offset, bytes] : writes) {
      if (static_cast<haddr_t>(offset) == time[k].address && bytes == block_bytes) ++at_block;
      for (const H5File::ChunkPlace* place : {&time[k], &position[k], &energy[k]})
        if (static_cast<haddr_t>(offset) == place->address && bytes == place->bytes) ++at_a_series_chunk;
    }
    EXPECT_EQ(at_block, 1) << "block " << k << ": writes of the whole block at its first chunk";
    EXPECT_EQ(at_a_series_chunk, 0) << "block " << k << ": writes of one series' chunk";
  }
  std::filesystem::remove(path);
}

TEST(InterruptedRuns, AWriterKilledAtEveryWriteLeavesWholeSamples) {
  const std::string path = temporary("killed_at_every_write.h5");
  // How many writes a whole run makes: count them in a child that is not killed.
  long total_writes = 0;
  {
    int channel[2];
    ASSERT_EQ(pipe(channel), 0);
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      writes_before_kill = 1L << 40;
      write_run(path);
      const long made = (1L << 40) - writes_before_kill;
      [[maybe_unused]] const ssize_t sent = write(channel[1], &made, sizeof made);
      _exit(0);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    ASSERT_EQ(read(channel[0], &total_writes, sizeof total_writes), static_cast<ssize_t>(sizeof total_writes));
    close(channel[0]);
    close(channel[1]);
  }
  ASSERT_GT(total_writes, 10);
  int absent = 0, whole = 0;
  for (long kill_at = 0; kill_at < total_writes; ++kill_at) {
    std::filesystem::remove(path);
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      writes_before_kill = kill_at;
      write_run(path);
      _exit(0);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "write " << kill_at << " was not reached";
    if (!std::filesystem::exists(path)) {
      // Killed while the layout was built: the name never points at a half-built file.
      ++absent;
      continue;
    }
    const std::string problem = whole_samples_problem(path);
    EXPECT_EQ(problem, "") << "killed at write " << kill_at << " of " << total_writes;
    whole += problem.empty();
  }
  EXPECT_GT(whole, total_writes / 2);  // most kill points are after the file appeared
  EXPECT_LT(absent, total_writes / 2);
  std::filesystem::remove(path);
  std::filesystem::remove(path + ".partial");
}

/// A run of tests/cases/long_run.yaml (a pendulum) shortened to about half a second of
/// wall time with ~6000 samples: several flushes of 1024 samples.
std::vector<std::string> pendulum_arguments(const std::string& output) {
  return {testing::heavesim_binary(),
          "run",
          testing::source_path("tests/cases/long_run.yaml"),
          "-o",
          output,
          "--quiet",
          "--set",
          "solver.t_end=0.3",
          "--set",
          "output.interval=5e-5"};
}

pid_t spawn(const std::vector<std::string>& arguments) {
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return -1;
  return pid;
}

void kill_runs_at_random_moments(int kills) {
  const std::string reference_path = temporary("pendulum_reference.h5"), path = temporary("pendulum_killed.h5");
  const auto start = std::chrono::steady_clock::now();
  const pid_t reference_pid = spawn(pendulum_arguments(reference_path));
  ASSERT_GT(reference_pid, 0);
  int status = 0;
  waitpid(reference_pid, &status, 0);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  H5File reference(reference_path);
  ASSERT_TRUE(reference.ok());
  const std::vector<double> reference_time = reference.read("/time"), reference_q = reference.read("/joints/pivot/q");
  ASSERT_GT(reference_time.size(), 4096u);

  std::mt19937 random(20261124);
  std::uniform_real_distribution<double> moment(0.0, 1.1 * wall);
  int with_samples = 0;
  for (int kill_number = 0; kill_number < kills; ++kill_number) {
    std::filesystem::remove(path);
    const double delay = moment(random);
    const pid_t pid = spawn(pendulum_arguments(path));
    ASSERT_GT(pid, 0);
    std::this_thread::sleep_for(std::chrono::duration<double>(delay));
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    if (!std::filesystem::exists(path)) continue;  // killed before its layout was on disk
    SCOPED_TRACE("killed after " + std::to_string(delay) + " s");
    H5File file(path);
    ASSERT_TRUE(file.ok());
    const long written = file.long_attribute("/", "samples_written");
    ASSERT_GE(written, 0);
    const hsize_t rows = file.shape("/time")[0];
    ASSERT_GE(rows, static_cast<hsize_t>(written));
    for (const char* series : {"/joints/pivot/q", "/joints/pivot/reaction_force", "/bodies/bob/velocity",
                               "/signals/total_energy"})
      EXPECT_EQ(file.shape(series)[0], rows) << series;
    const std::vector<double> time = file.read("/time"), q = file.read("/joints/pivot/q");
    for (long k = 0; k < written; ++k) {
      ASSERT_EQ(time[k], reference_time[k]) << "sample " << k;
      ASSERT_EQ(q[k], reference_q[k]) << "sample " << k;
    }
    with_samples += written > 0;
  }
  EXPECT_GT(with_samples, kills / 3);  // the kills were spread over the run, not all at its start
  std::filesystem::remove(path);
  std::filesystem::remove(path + ".partial");
  std::filesystem::remove(reference_path);
}

TEST(InterruptedRuns, RunsKilledAtRandomMomentsHoldAPrefixOfTheUninterruptedRun) { kill_runs_at_random_moments(10); }

// The same with 48 kills: --gtest_also_run_disabled_tests --gtest_filter='*ManyRandomMoments*'.
TEST(InterruptedRuns, DISABLED_RunsKilledAtManyRandomMoments) { kill_runs_at_random_moments(48); }

TEST(InterruptedRuns, SigtermInTheFirstMillisecondsStopsCleanly) {
  const std::string path = temporary("early_sigterm.h5");
  const std::string binary = testing::heavesim_binary();
  for (const int delay_ms : {0, 2, 5, 10, 20, 40, 80, 160}) {
    SCOPED_TRACE("SIGTERM after " + std::to_string(delay_ms) + " ms");
    std::filesystem::remove(path);
    const pid_t pid = spawn({binary, "run", testing::source_path("tests/cases/long_run.yaml"), "-o", path, "--quiet"});
    ASSERT_GT(pid, 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
    kill(pid, SIGTERM);
    int status = 0;
    waitpid(pid, &status, 0);
    // Before the handler exists (the first instructions of the process) SIGTERM still
    // kills: that is the only signal death allowed, and only with no file written.
    if (WIFSIGNALED(status)) {
      EXPECT_EQ(WTERMSIG(status), SIGTERM);
      EXPECT_FALSE(std::filesystem::exists(path));
      continue;
    }
    EXPECT_EQ(WEXITSTATUS(status), 1);
    EXPECT_FALSE(std::filesystem::exists(path + ".partial"));
    if (!std::filesystem::exists(path)) continue;  // stopped before the run: nothing written
    H5File file(path);
    ASSERT_TRUE(file.ok());
    EXPECT_EQ(file.long_attribute("/", "complete"), 0);
    const long written = file.long_attribute("/", "samples_written");
    EXPECT_GE(written, 1);
    // An orderly stop leaves no unwritten rows: every series ends at samples_written.
    EXPECT_EQ(file.shape("/time")[0], static_cast<hsize_t>(written));
    EXPECT_EQ(file.shape("/joints/pivot/reaction_force")[0], static_cast<hsize_t>(written));
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace heavesim
