// Reading a result file while its run writes it (docs/result-file.md, "Reading while the
// run writes"): a plain reader (HDF5's default file locking, no SWMR, no
// HDF5_USE_FILE_LOCKING) opens the file as the run goes, twice, and sees the sample
// count grow and whole samples, the values the finished file holds.
#include <gtest/gtest.h>

#include <hdf5.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "tests/app/h5_file.hpp"
#include "tests/test_support.hpp"

extern char** environ;

namespace heavesim {
namespace {

/// A reader of the file as it is now: opened plainly (HDF5's default file locking, no
/// SWMR), samples_written and the first rows of /time, closed again. Reopening is how a
/// reader sees what the writer has added (HDF5 caches what it has read).
struct Snapshot {
  long samples_written = -1;
  std::vector<double> time;
};
Snapshot read_now(const std::string& path) {
  Snapshot snapshot;
  hid_t file = -1;
  H5E_BEGIN_TRY { file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT); } H5E_END_TRY;
  if (file < 0) return snapshot;
  const hid_t attribute = H5Aopen(file, "samples_written", H5P_DEFAULT);
  H5Aread(attribute, H5T_NATIVE_LONG, &snapshot.samples_written);
  H5Aclose(attribute);
  if (snapshot.samples_written > 0) {
    snapshot.time.resize(snapshot.samples_written);
    const hid_t dataset = H5Dopen2(file, "/time", H5P_DEFAULT);
    const hsize_t start = 0, count = static_cast<hsize_t>(snapshot.samples_written);
    const hid_t file_space = H5Dget_space(dataset), memory_space = H5Screate_simple(1, &count, nullptr);
    H5Sselect_hyperslab(file_space, H5S_SELECT_SET, &start, nullptr, &count, nullptr);
    H5Dread(dataset, H5T_NATIVE_DOUBLE, memory_space, file_space, H5P_DEFAULT, snapshot.time.data());
    H5Sclose(memory_space);
    H5Sclose(file_space);
    H5Dclose(dataset);
  }
  H5Fclose(file);
  return snapshot;
}

TEST(LiveReading, AReaderSeesTheSampleCountGrowAndTheValuesOfTheFinishedFile) {
  const std::string path = temporary("live.h5");
  std::filesystem::remove(path);
  // The slow pendulum (rk4 at 1e-6 s) for about 1.2 s of wall time: 48,000 samples in
  // blocks of 1024, committed (samples_written raised) at most every 0.25 s of wall
  // time (ResultFile::commit_interval_s), so several times while the reader looks.
  const std::vector<std::string> arguments = {testing::heavesim_binary(), "run",
                                              testing::source_path("tests/cases/long_run.yaml"), "-o", path, "--quiet",
                                              "--set", "solver.t_end=2.4", "--set", "output.interval=5e-5"};
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ), 0);

  // Wait for the file to appear (published at its first flush) and open it as it is written.
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&start] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  Snapshot first;
  while (elapsed() < 20.0 && first.samples_written <= 0) {
    if (std::filesystem::exists(path)) first = read_now(path);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_GT(first.samples_written, 0) << "the file did not open while the run wrote it";
  Snapshot second = first;
  while (second.samples_written == first.samples_written && elapsed() < 20.0) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    const Snapshot now = read_now(path);
    if (now.samples_written >= 0) second = now;
  }
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  // Both reads were made while the run went on, in whole blocks of 1024 samples.
  const long first_count = first.samples_written, second_count = second.samples_written;
  EXPECT_GT(second_count, first_count);
  EXPECT_LT(second_count, 48001);
  EXPECT_EQ(first_count % 1024, 0);
  EXPECT_EQ(second_count % 1024, 0);

  H5File finished(path);
  ASSERT_TRUE(finished.ok());
  EXPECT_EQ(finished.long_attribute("/", "complete"), 1);
  const std::vector<double> time = finished.read("/time");
  ASSERT_EQ(time.size(), 48001u);
  for (long k = 0; k < second_count; ++k) {
    if (k < first_count) {
      ASSERT_EQ(first.time[k], time[k]) << "sample " << k;
    }
    ASSERT_EQ(second.time[k], time[k]) << "sample " << k;
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace heavesim
