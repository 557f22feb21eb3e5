#include <fmt/format.h>

#include <algorithm>
#include <chrono>

#include "cli/commands/commands.hpp"
#include "validation/checks/validation_suite.hpp"

namespace heavesim {

int validate_command(const std::vector<std::string>& names, bool list_only) {
  using validation::ValidationCheck;
  using validation::ValidationRow;
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

  fmt::print("{:<4} {:<52} {:<46} {:>10} {:>10}  {}\n", "id", "case", "quantity", "max error", "tolerance", "result");
  int failures = 0;
  for (const ValidationCheck& check : checks) {
    if (!names.empty() && std::find(names.begin(), names.end(), check.id) == names.end()) continue;
    const auto start = std::chrono::steady_clock::now();
    std::vector<ValidationRow> rows;
    try {
      rows = check.run();
    } catch (const std::exception& error) {
      fmt::print("{:<4} {:<52} {:<46} {:>10} {:>10}  FAIL ({})\n", check.id, check.title.substr(0, 52), "(did not run)",
                 "-", "-", error.what());
      ++failures;
      continue;
    }
    for (const ValidationRow& row : rows) {
      fmt::print("{:<4} {:<52} {:<46} {:>10.2e} {:>10.0e}  {}\n", row.check, row.subject, row.quantity, row.max_error,
                 row.tolerance, row.passed() ? "PASS" : "FAIL");
      failures += !row.passed();
    }
    fmt::print("     ({:.2f} s)\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  fmt::print("{}\n", failures == 0 ? "all validation checks PASS" : fmt::format("{} validation rows FAIL", failures));
  return failures == 0 ? 0 : 1;
}

}  // namespace heavesim
