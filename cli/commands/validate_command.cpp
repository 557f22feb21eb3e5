#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <optional>
#include <thread>

#include "cli/commands/commands.hpp"
#include "validation/checks/validation_suite.hpp"

namespace heavesim {
namespace {

using validation::ValidationCheck;
using validation::ValidationRow;

/// One check's outcome: its rows, or the error that stopped it, and its wall time.
struct CheckOutcome {
  std::vector<ValidationRow> rows;
  std::optional<std::string> error;  // set: the check threw (its what() may be empty)
  double seconds = 0.0;
};

/// Prints one check's rows in the table's format; returns the number of failed rows.
int print_outcome(const ValidationCheck& check, const CheckOutcome& outcome) {
  if (outcome.error) {
    fmt::print("{:<4} {:<52} {:<46} {:>10} {:>10}  FAIL ({})\n", check.id, check.title.substr(0, 52), "(did not run)",
               "-", "-", *outcome.error);
    return 1;
  }
  int failures = 0;
  for (const ValidationRow& row : outcome.rows) {
    fmt::print("{:<4} {:<52} {:<46} {:>10.2e} {:>10.0e}  {}\n", row.check, row.subject, row.quantity, row.max_error,
               row.tolerance, row.passed() ? "PASS" : "FAIL");
    failures += !row.passed();
  }
  fmt::print("     ({:.2f} s)\n", outcome.seconds);
  std::fflush(stdout);
  return failures;
}

CheckOutcome run_check(const ValidationCheck& check) {
  CheckOutcome outcome;
  const auto start = std::chrono::steady_clock::now();
  try {
    outcome.rows = check.run();
  } catch (const std::exception& error) {
    outcome.error = error.what();
  } catch (...) {  // on a worker thread nothing may escape (std::terminate)
    outcome.error = "an exception that is not a std::exception";
  }
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

}  // namespace

int validate_command(const std::vector<std::string>& names, bool list_only, int jobs) {
  const std::vector<ValidationCheck>& checks = validation::validation_checks();
  for (const std::string& name : names)
    if (std::none_of(checks.begin(), checks.end(), [&](const ValidationCheck& c) { return c.id == name; })) {
      fmt::print(stderr, "heavesim: unknown validation check '{}'; known:", name);
      for (const ValidationCheck& check : checks) fmt::print(stderr, " {}", check.id);
      fmt::print(stderr, "\n");
      return 2;
    }
  if (list_only) {
    for (const ValidationCheck& check : checks) fmt::print("{:<4} {}\n", check.id, check.title);
    return 0;
  }
  std::vector<const ValidationCheck*> selected;
  for (const ValidationCheck& check : checks)
    if (names.empty() || std::find(names.begin(), names.end(), check.id) != names.end()) selected.push_back(&check);

  // The checks are independent (each builds its own models, integrators and files), so
  // `jobs` threads take them in turn (one thread with -j 1: the same path); this thread
  // prints the table in the suite's order, each check as soon as it and every check
  // before it are done. A check's own wall time is its own, but with other checks beside
  // it on the same cores.
  std::vector<std::optional<CheckOutcome>> outcomes(selected.size());
  std::mutex mutex;
  std::condition_variable finished;
  std::size_t next = 0;
  const auto work = [&] {
    for (;;) {
      std::size_t index;
      {
        const std::lock_guard lock(mutex);
        if (next == selected.size()) return;
        index = next++;
      }
      CheckOutcome outcome = run_check(*selected[index]);
      {
        const std::lock_guard lock(mutex);
        outcomes[index] = std::move(outcome);
      }
      finished.notify_one();
    }
  };
  const std::size_t thread_count = std::min<std::size_t>(std::max(jobs, 1), selected.size());
  std::vector<std::jthread> threads;  // joined at return, after the last check is printed
  threads.reserve(thread_count);
  for (std::size_t t = 0; t < thread_count; ++t) threads.emplace_back(work);

  fmt::print("{:<4} {:<52} {:<46} {:>10} {:>10}  {}\n", "id", "case", "quantity", "max error", "tolerance", "result");
  std::fflush(stdout);
  int failures = 0;
  for (std::size_t i = 0; i < selected.size(); ++i) {
    std::unique_lock lock(mutex);
    finished.wait(lock, [&] { return outcomes[i].has_value(); });
    const CheckOutcome outcome = std::move(*outcomes[i]);
    lock.unlock();
    failures += print_outcome(*selected[i], outcome);
  }
  fmt::print("{}\n", failures == 0 ? "all validation checks PASS" : fmt::format("{} validation rows FAIL", failures));
  return failures == 0 ? 0 : 1;
}

}  // namespace heavesim
