#include "cli/commands/project_script.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <fmt/format.h>

#include "app/version.hpp"

extern char** environ;

namespace heavesim {
namespace {

const std::string python = "/usr/bin/python3";

struct CommandLine {
  std::vector<std::string> words;
  std::vector<char*> argv;
  CommandLine(const std::string& script, const std::vector<std::string>& arguments)
      : words{python, std::string(heavesim_source_dir) + "/scripts/" + script} {
    words.insert(words.end(), arguments.begin(), arguments.end());
    for (std::string& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
  }
};

}  // namespace

int exec_project_script(const std::string& script, const std::vector<std::string>& arguments) {
  CommandLine line(script, arguments);
  std::fflush(nullptr);
  execv(python.c_str(), line.argv.data());
  // execv returns only when it failed.
  fmt::print(stderr, "heavesim: error: cannot run {} {}: {}\n", python, line.words[1], std::strerror(errno));
  return 1;
}

int run_project_script(const std::string& script, const std::vector<std::string>& arguments) {
  CommandLine line(script, arguments);
  std::fflush(nullptr);
  pid_t pid = 0;
  if (const int error = posix_spawn(&pid, python.c_str(), nullptr, nullptr, line.argv.data(), environ); error != 0) {
    fmt::print(stderr, "heavesim: error: cannot run {} {}: {}\n", python, line.words[1], std::strerror(error));
    return 1;
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

}  // namespace heavesim
