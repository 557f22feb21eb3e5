// What a heavesim process loads at its start (docs/performance.md, "Issue #18, seventeenth
// round"): the dynamic loader's own account (LD_DEBUG=files) of a whole run, so that a
// library loaded later by dlopen counts too, not our reading of the link line.
#include <gtest/gtest.h>

#include <set>
#include <sstream>
#include <string>

#include "tests/test_support.hpp"

namespace heavesim {
namespace {

/// The file names (no directory) of the shared objects the loader loaded while `command`
/// ran, from its "file=NAME [0];  needed by ..." / "file=NAME [0];  dynamically loaded
/// by ..." lines.
std::set<std::string> loaded_objects(const std::string& command) {
  const testing::CommandResult result = testing::run_command_line("LD_DEBUG=files " + command);
  // A run that stopped early would have loaded less than a whole one.
  EXPECT_EQ(result.exit_code, 0) << result.output.substr(result.output.size() > 2000 ? result.output.size() - 2000 : 0);
  std::set<std::string> names;
  std::istringstream lines(result.output);
  for (std::string line; std::getline(lines, line);) {
    const std::size_t at = line.find("file=");
    if (at == std::string::npos) continue;
    std::string name = line.substr(at + 5, line.find_first_of(" [;", at + 5) - (at + 5));
    if (const std::size_t slash = name.rfind('/'); slash != std::string::npos) name = name.substr(slash + 1);
    names.insert(name);
  }
  return names;
}

bool starts_with(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

// Debian's shared HDF5 brought libcurl, OpenSSL, GnuTLS, Kerberos and LDAP (its S3
// driver), and Open MPI was linked into every process: 60 shared objects in this run, ~20 ms
// of a 0.13 s drilling run (23 now). The executable now links HDF5's static archive, loads the MPI
// module only under mpirun (app/sweep/mpi_module.cpp; the MPI sweep test covers that
// side) and hashes with Nettle.
TEST(ProcessStart, ARunLoadsNeitherMpiNorTheS3DriversLibrariesNorOpenSsl) {
  const std::string output = ::testing::TempDir() + "process_start.h5";
  const std::set<std::string> names =
      loaded_objects(testing::heavesim_binary() + " run " +
                     testing::source_path("cases/c1_heave_decay/h0_locked.yaml") + " -o " + output + " -q");
  // The account was read: the C library and one heavesim needs are in it.
  ASSERT_TRUE(names.count("libc.so.6")) << "no LD_DEBUG account of the run";
  EXPECT_TRUE(names.count("libyaml-cpp.so.0.7"));
  for (const std::string& name : names) {
    for (const char* unwanted : {"libmpi", "libopen-rte", "libopen-pal", "libhwloc", "libheavesim_mpi", "libcurl",
                                 "libcrypto", "libssl", "libgnutls", "libkrb5", "libldap", "libhdf5"})
      EXPECT_FALSE(starts_with(name, unwanted)) << name << " was loaded by a plain run";
  }
  EXPECT_LE(names.size(), 30u) << "shared objects loaded: " << names.size();
}

}  // namespace
}  // namespace heavesim
