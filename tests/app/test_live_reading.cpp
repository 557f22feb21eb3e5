// Reading a result file while its run writes it (docs/result-file.md, "Reading while the
// run writes"): the writer is in SWMR mode, a reader opens the file with
// H5F_ACC_SWMR_READ, refreshes what it holds and sees whole samples, the same values the
// finished file holds.
#include <gtest/gtest.h>

#include <hdf5.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <thread>

#include "tests/app/h5_file.hpp"
#include "tests/test_support.hpp"

extern char** environ;

namespace heavesim {
namespace {

/// A SWMR reader of one file: the root's samples_written and the first rows of /time.
class LiveReader {
 public:
  explicit LiveReader(const std::string& path) {
    H5E_BEGIN_TRY { file_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY | H5F_ACC_SWMR_READ, H5P_DEFAULT); } H5E_END_TRY;
    if (file_ < 0) return;
    root_ = H5Gopen2(file_, "/", H5P_DEFAULT);
    time_ = H5Dopen2(file_, "/time", H5P_DEFAULT);
  }
  ~LiveReader() {
    if (time_ >= 0) H5Dclose(time_);
    if (root_ >= 0) H5Gclose(root_);
    if (file_ >= 0) H5Fclose(file_);
  }
  bool ok() const { return file_ >= 0 && root_ >= 0 && time_ >= 0; }
  /// samples_written as the writer last flushed it: the reader's cached copy of the
  /// root's header and of /time's is dropped first (H5Orefresh, H5Drefresh).
  long samples_written() {
    if (H5Orefresh(root_) < 0 || H5Drefresh(time_) < 0) return -1;
    long value = -1;
    const hid_t attribute = H5Aopen(root_, "samples_written", H5P_DEFAULT);
    H5Aread(attribute, H5T_NATIVE_LONG, &value);
    H5Aclose(attribute);
    return value;
  }
  std::vector<double> time(long rows) const {
    std::vector<double> values(rows);
    const hsize_t start = 0, count = static_cast<hsize_t>(rows);
    const hid_t file_space = H5Dget_space(time_), memory_space = H5Screate_simple(1, &count, nullptr);
    H5Sselect_hyperslab(file_space, H5S_SELECT_SET, &start, nullptr, &count, nullptr);
    H5Dread(time_, H5T_NATIVE_DOUBLE, memory_space, file_space, H5P_DEFAULT, values.data());
    H5Sclose(memory_space);
    H5Sclose(file_space);
    return values;
  }

 private:
  hid_t file_ = -1, root_ = -1, time_ = -1;
};

TEST(LiveReading, ASwmrReaderSeesTheSampleCountGrowAndTheValuesOfTheFinishedFile) {
  const std::string path = temporary("live.h5");
  std::filesystem::remove(path);
  // The slow pendulum (rk4 at 1e-6 s) for about 2 s of wall time: 24,000 samples, a
  // flush every 1024.
  const std::vector<std::string> arguments = {testing::heavesim_binary(), "run",
                                              testing::source_path("tests/cases/long_run.yaml"), "-o", path, "--quiet",
                                              "--set", "solver.t_end=1.2", "--set", "output.interval=5e-5"};
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ), 0);

  // Wait for the file to appear (published at its first flush) and open it as it is written.
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&start] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  std::unique_ptr<LiveReader> reader;
  long first = 0;
  while (elapsed() < 20.0) {
    if (std::filesystem::exists(path)) {
      if (!reader) reader = std::make_unique<LiveReader>(path);
      if (!reader->ok()) reader.reset();
      else if ((first = reader->samples_written()) > 0) break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_TRUE(reader) << "the file did not open while the run wrote it";
  ASSERT_GT(first, 0);
  const std::vector<double> first_time = reader->time(first);
  long second = first;
  while (second == first && elapsed() < 20.0) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    second = reader->samples_written();
  }
  const std::vector<double> second_time = reader->time(second);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  // Both reads were made while the run went on, in whole flushes of 1024 samples.
  EXPECT_GT(second, first);
  EXPECT_LT(second, 24001);
  EXPECT_EQ(first % 1024, 0);
  EXPECT_EQ(second % 1024, 0);
  reader.reset();

  // The finished file opens for any reader (not only SWMR ones): the writer closed it.
  const hid_t plain = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(plain, 0);
  H5Fclose(plain);
  H5File finished(path);
  ASSERT_TRUE(finished.ok());
  EXPECT_EQ(finished.long_attribute("/", "complete"), 1);
  const std::vector<double> time = finished.read("/time");
  ASSERT_EQ(time.size(), 24001u);
  for (long k = 0; k < second; ++k) {
    if (k < first) ASSERT_EQ(first_time[k], time[k]) << "sample " << k;
    ASSERT_EQ(second_time[k], time[k]) << "sample " << k;
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace heavesim
