#pragma once
// The commands whose work is a Python script of the project (operability, report, the
// RAO figure): run with Debian's /usr/bin/python3, which has numpy, scipy, h5py and
// matplotlib (python3-*), not a python3 earlier on PATH that may lack them.
#include <string>
#include <vector>

namespace heavesim {

/// Replaces this process with `/usr/bin/python3 <source>/scripts/<script> arguments...`
/// (exec), so the command's exit code is the script's. Returns 1, having said why on
/// stderr, only if the exec failed.
int exec_project_script(const std::string& script, const std::vector<std::string>& arguments);

/// Runs the same as a child process and waits for it: its exit code, 1 if it could not
/// start or did not exit normally.
int run_project_script(const std::string& script, const std::vector<std::string>& arguments);

}  // namespace heavesim
