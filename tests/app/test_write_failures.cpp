// Output that cannot be written (docs/result-file.md, "When the disk is full"): a
// file-size limit (RLIMIT_FSIZE, EFBIG: works without privileges), a full file system
// (a 1 MiB tmpfs, when this process may mount one), a CSV on /dev/full (ENOSPC on
// every write), and output paths that cannot be used. Each must stop the run with exit
// code 1, a message naming the file and the system's cause, and leave the result file
// readable with whole samples and complete = 0 (or no file at all).
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "app/output/result_file.hpp"
#include "tests/app/h5_file.hpp"
#include "tests/test_support.hpp"

namespace heavesim {
namespace {

// A pendulum recorded at 20001 samples: a 5.3 MB result file
// (reserved at its full length, sparse) and a 6.5 MB CSV.
const std::string pendulum = "tests/cases/long_run.yaml";
const std::string pendulum_settings = "--quiet --set solver.t_end=2 --set output.interval=1e-4 --set solver.step=1e-4";

/// `command` under a file-size limit of `kibibytes` (bash counts ulimit -f in KiB; the
/// /bin/sh of popen may count in 512-byte blocks).
std::string with_file_size_limit(int kibibytes, const std::string& command) {
  return "bash -c 'ulimit -f " + std::to_string(kibibytes) + " && exec " + command + "'";
}

/// The first `samples_written` rows are whole samples of the pendulum: times on the grid.
void expect_whole_samples(const std::string& path, double interval) {
  H5File file(path);
  ASSERT_TRUE(file.ok()) << path;
  EXPECT_EQ(file.long_attribute("/", "complete"), 0);
  const long written = file.long_attribute("/", "samples_written");
  ASSERT_GE(written, 0);
  const hsize_t rows = file.shape("/time")[0];
  EXPECT_GE(rows, static_cast<hsize_t>(written));
  EXPECT_EQ(file.shape("/joints/pivot/reaction_force")[0], rows);
  const std::vector<double> time = file.read("/time");
  for (long k = 0; k < written; ++k) ASSERT_NEAR(time[k], k * interval, 1e-9) << "sample " << k;
}

TEST(WriteFailures, AFailedHdf5WriteIsReportedAndLeavesWholeSamples) {
  // In a child limited to 400 kB per file (EFBIG past it), a writer growing its series
  // as it goes (no reservation) fails in the middle of its samples.
  const std::string path = temporary("file_size_limit.h5");
  int channel[2];
  ASSERT_EQ(pipe(channel), 0);
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{400000, 400000};
    setrlimit(RLIMIT_FSIZE, &limit);
    try {
      ResultFile file(path);
      std::vector<int> series;
      for (int s = 0; s < 20; ++s) series.push_back(file.add_series(s == 0 ? "/time" : "/signals/s" + std::to_string(s), 0, "-", "-"));
      file.flush();
      for (int k = 0; k < 20000; ++k) {
        const double value = k;
        for (int id : series) file.append(id, &value);
        file.end_sample();
      }
      file.close();
    } catch (const OutputError& error) {
      const std::string message = error.what();
      [[maybe_unused]] const ssize_t sent = write(channel[1], message.data(), message.size());
      _exit(1);
    }
    _exit(0);
  }
  close(channel[1]);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "the writer died of signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 1);
  char buffer[1024] = {};
  [[maybe_unused]] const ssize_t received = read(channel[0], buffer, sizeof buffer - 1);
  close(channel[0]);
  const std::string message = buffer;
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("File too large"), std::string::npos) << message;
  H5File file(path);
  ASSERT_TRUE(file.ok());
  const long written = file.long_attribute("/", "samples_written");
  EXPECT_GE(written, 1024);  // at least the first chunk of samples (164 kB) fitted in 400 kB
  EXPECT_LT(written, 20000);
  const std::vector<double> time = file.read("/time"), last = file.read("/signals/s19");
  ASSERT_GE(time.size(), static_cast<std::size_t>(written));
  ASSERT_GE(last.size(), static_cast<std::size_t>(written));
  for (long k = 0; k < written; ++k) ASSERT_TRUE(time[k] == k && last[k] == k) << "sample " << k;
  std::filesystem::remove(path);
}

TEST(WriteFailures, AResultFileLargerThanTheFileSizeLimitStopsTheRunAtItsStart) {
  // The result file takes its full length at the start: under `ulimit -f 1024` (1 MiB)
  // the 5.3 MB file fails there (its layout, made on the recorder's thread beside the first
  // steps where the machine has two cores, and reported by the first hand-over of samples
  // after it; in line on one core), and no file is left behind.
  const std::string output = temporary("limited.h5");
  const testing::CommandResult result = testing::run_command_line(with_file_size_limit(
      1024, testing::heavesim_binary() + " run " + testing::source_path(pendulum) + " -o " + output + " " +
                pendulum_settings));
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find(output), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("File too large"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("no result file was written"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(output));
  EXPECT_FALSE(std::filesystem::exists(output + ".partial"));
}

TEST(WriteFailures, ACsvPastTheFileSizeLimitStopsTheRunAndTheResultFileStaysWhole) {
  // 5900 KiB: room for the 5.3 MB result file, not for the 6.5 MB CSV, which fails mid-run.
  const std::string output = temporary("csv_limited.h5"), csv_directory = temporary("csv_limited");
  const testing::CommandResult result = testing::run_command_line(with_file_size_limit(
      5900, testing::heavesim_binary() + " run " + testing::source_path(pendulum) + " -o " + output + " --csv " +
                csv_directory + " " + pendulum_settings));
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find(csv_directory + "/long_run.csv"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("File too large"), std::string::npos) << result.output;
  expect_whole_samples(output, 1e-4);
  H5File file(output);
  // Closed in order: the series end at samples_written, which is part of the run.
  const long written = file.long_attribute("/", "samples_written");
  EXPECT_EQ(file.shape("/time")[0], static_cast<hsize_t>(written));
  EXPECT_GT(written, 0);
  EXPECT_LT(written, 20001);
  // ... and the statistics of the samples recorded were written (the recorder finished):
  // the largest time is the last sample's (the recorder's and the file's blocks agree
  // after a CSV failure inside a sample).
  EXPECT_EQ(result.output.find("heavesim: error:"), std::string::npos) << result.output;
  EXPECT_EQ(file.double_attribute("/time", "maximum"), file.read("/time").back());
  std::filesystem::remove(output);
  std::filesystem::remove_all(csv_directory);
}

TEST(WriteFailures, ACsvOnAFullDeviceStopsTheRun) {
  // <dir>/long_run.csv is /dev/full: every write fails with ENOSPC.
  const std::string output = temporary("csv_full.h5"), csv_directory = temporary("csv_full");
  std::filesystem::create_directories(csv_directory);
  std::filesystem::create_symlink("/dev/full", csv_directory + "/long_run.csv");
  const testing::CommandResult result = testing::run_command_line(
      testing::heavesim_binary() + " run " + testing::source_path(pendulum) + " -o " + output + " --csv " +
      csv_directory + " " + pendulum_settings);
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find(csv_directory + "/long_run.csv"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("No space left on device"), std::string::npos) << result.output;
  if (std::filesystem::exists(output)) expect_whole_samples(output, 1e-4);
  std::filesystem::remove(output);
  std::filesystem::remove_all(csv_directory);
}

TEST(WriteFailures, AFullFileSystemStopsTheRunAndLeavesWholeSamples) {
  const std::string mount_point = temporary("full_disk");
  std::filesystem::create_directories(mount_point);
  if (std::system(("mount -t tmpfs -o size=1m tmpfs " + mount_point + " 2>/dev/null").c_str()) != 0) {
    std::filesystem::remove(mount_point);
    GTEST_SKIP() << "cannot mount a tmpfs here (needs root); the file-size-limit tests cover the write failures";
  }
  const std::string output = mount_point + "/pendulum.h5";
  const testing::CommandResult result = testing::run_command_line(
      testing::heavesim_binary() + " run " + testing::source_path(pendulum) + " -o " + output + " " + pendulum_settings);
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find(output), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("No space left on device"), std::string::npos) << result.output;
  // The failure is met by the block writer's thread: reported by heavesim alone, without
  // HDF5's own error dump (which a thread-safe HDF5 prints per thread unless told not to).
  EXPECT_EQ(result.output.find("HDF5-DIAG"), std::string::npos) << result.output;
  expect_whole_samples(output, 1e-4);
  EXPECT_GT(H5File(output).long_attribute("/", "samples_written"), 0);
  EXPECT_EQ(std::system(("umount " + mount_point).c_str()), 0);
  std::filesystem::remove(mount_point);
}

TEST(WriteFailures, UnusableOutputPathsAreReportedBeforeTheRun) {
  const std::string directory = temporary("output_is_a_directory");
  std::filesystem::create_directories(directory);
  testing::CommandResult result = testing::run_case(pendulum, directory, "--quiet");
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find(directory), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("is a directory"), std::string::npos) << result.output;
  std::filesystem::remove(directory);

  const std::string file = temporary("a_regular_file");
  std::ofstream(file) << "x";
  result = testing::run_case(pendulum, file + "/sub/out.h5", "--quiet");
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("cannot create the directory"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("Not a directory"), std::string::npos) << result.output;
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace heavesim
