#include "app/sweep/sweep_plan.hpp"

#include <cmath>
#include <random>

#include <fmt/format.h>

#include "app/case/case_merge.hpp"
#include "app/case/sha256.hpp"
#include "app/version.hpp"

namespace heavesim {
namespace {

/// The value of a number as --set text: the shortest text that reads back to it.
std::string number_text(double value) { return fmt::format("{}", value); }

/// Uniform on [0, 1) from the top 53 bits of one draw: the same on every platform
/// (std::uniform_real_distribution is not specified bit for bit).
double unit_uniform(std::mt19937_64& generator) { return static_cast<double>(generator() >> 11) * 0x1p-53; }

/// One row per sample, one column per variable: a Latin hypercube (McKay, Beckman and
/// Conover 1979): each variable's interval is cut into N equal strata, every stratum is
/// sampled once at a uniform point inside it, and the strata are paired across variables
/// by independent random permutations (Fisher-Yates).
std::vector<std::vector<double>> latin_hypercube(const std::vector<SweepVariable>& variables, long samples,
                                                 unsigned long long seed) {
  std::mt19937_64 generator(seed);
  const auto n = static_cast<std::size_t>(samples);
  std::vector<std::vector<double>> rows(n, std::vector<double>(variables.size()));
  std::vector<std::size_t> strata(n);
  for (std::size_t j = 0; j < variables.size(); ++j) {
    for (std::size_t i = 0; i < n; ++i) strata[i] = i;
    for (std::size_t i = n; i > 1; --i) std::swap(strata[i - 1], strata[generator() % i]);
    const auto [from, to] = *variables[j].sample;
    for (std::size_t i = 0; i < n; ++i)
      rows[i][j] = from + (to - from) * (static_cast<double>(strata[i]) + unit_uniform(generator)) / static_cast<double>(n);
  }
  return rows;
}

/// The variants: one row of values per combination of the variables (no variable: one empty row).
std::vector<std::vector<std::size_t>> variant_indices(const SweepDefinition& sweep) {
  const std::vector<SweepVariable>& variables = sweep.variables;
  std::vector<std::vector<std::size_t>> rows;
  if (variables.empty()) return {{}};
  if (sweep.sampling == Sampling::zip) {
    for (std::size_t i = 0; i < variables.front().values.size(); ++i) rows.push_back(std::vector<std::size_t>(variables.size(), i));
    return rows;
  }
  // Grid: the last variable varies fastest.
  std::vector<std::size_t> counter(variables.size(), 0);
  for (;;) {
    rows.push_back(counter);
    std::size_t j = variables.size();
    while (j > 0 && ++counter[j - 1] == variables[j - 1].values.size()) counter[--j] = 0;
    if (j == 0) return rows;
  }
}

}  // namespace

std::vector<std::string> PlannedRun::overrides() const {
  std::vector<std::string> texts;
  for (const SweepAssignment& assignment : assignments) texts.push_back(assignment.path + "=" + assignment.value);
  return texts;
}

std::string PlannedRun::describe(const std::vector<std::string>& columns) const {
  std::string text;
  for (std::size_t j = 0; j < columns.size(); ++j) text += fmt::format("{}{} = {}", j ? ", " : "", columns[j], values[j]);
  return text;
}

std::string run_hash(const std::string& resolved_yaml, const std::string& version) {
  return sha256_hex(resolved_yaml + "\n# heavesim " + version + "\n");
}

std::string run_hash(const std::string& resolved_yaml) { return run_hash(resolved_yaml, heavesim_version); }

InputError error_in_sweep(const PlannedRun& run, const std::vector<std::string>& columns, const InputError& error) {
  // apply_override names an override "--set <assignment>" (cut after 120 characters),
  // and the value it parsed "--set <path>"; a later assignment of a path overrides an
  // earlier one, so the last that matches is the one the case holds.
  const std::string& origin = error.location().file;
  for (auto assignment = run.assignments.rbegin(); assignment != run.assignments.rend(); ++assignment) {
    const std::string text = assignment->path + "=" + assignment->value;
    const std::string shown = text.size() > 120 ? text.substr(0, 120) + "..." : text;
    if (origin == "--set " + shown || origin == "--set " + assignment->path)
      return InputError(assignment->location, error.key_path(),
                        fmt::format("{} (run {}: {}; {})", error.found(), run.index, run.name, run.describe(columns)),
                        error.expected());
  }
  return error;
}

SweepPlan make_plan(const SweepDefinition& sweep) {
  SweepPlan plan;
  for (const SweepVariable& variable : sweep.variables) {
    plan.columns.push_back(variable.path);
    plan.column_paths.push_back(variable.path);
  }
  if (sweep.scatter) {
    plan.columns.insert(plan.columns.end(), {"Hs", "Tp"});
    plan.column_paths.insert(plan.column_paths.end(), {sweep.scatter->hs_path, sweep.scatter->tp_path});
  }

  // The variants' values and where the sweep file gives them.
  std::vector<std::vector<double>> variant_values;
  std::vector<std::vector<SourceLocation>> variant_locations;
  if (sweep.sampling == Sampling::latin_hypercube) {
    variant_values = latin_hypercube(sweep.variables, sweep.samples, sweep.seed);
    for (std::size_t i = 0; i < variant_values.size(); ++i) {
      std::vector<SourceLocation> locations;
      for (const SweepVariable& variable : sweep.variables) locations.push_back(variable.location);
      variant_locations.push_back(locations);
    }
  } else {
    for (const std::vector<std::size_t>& row : variant_indices(sweep)) {
      std::vector<double> values;
      std::vector<SourceLocation> locations;
      for (std::size_t j = 0; j < row.size(); ++j) {
        values.push_back(sweep.variables[j].values[row[j]]);
        locations.push_back(sweep.variables[j].value_locations[row[j]]);
      }
      variant_values.push_back(values);
      variant_locations.push_back(locations);
    }
  }

  struct SeaState {
    double hs, tp, probability;
  };
  std::vector<SeaState> sea_states;
  if (sweep.scatter) {
    const ScatterTable& table = sweep.scatter->table;
    for (std::size_t r = 0; r < table.hs.size(); ++r)
      for (std::size_t c = 0; c < table.tp.size(); ++c)
        if (table.occurrence[r][c] > 0.0) sea_states.push_back({table.hs[r], table.tp[c], table.occurrence[r][c] / table.total});
  }
  const std::size_t total =
      sweep.base_cases.size() * variant_values.size() * std::max<std::size_t>(sea_states.size(), 1);
  if (total > 1'000'000)
    throw InputError(sweep.sampling_location.file.empty() ? SourceLocation{sweep.sweep_file, 0, 0} : sweep.sampling_location,
                     "variables", fmt::format("{} runs", total), "at most 1e6 runs in one sweep");

  const std::size_t width = std::max<std::size_t>(4, fmt::format("{}", total - 1).size());
  for (const std::string& base_case : sweep.base_cases) {
    const CaseNode base = load_case_tree(base_case);
    for (std::size_t v = 0; v < variant_values.size(); ++v) {
      for (std::size_t s = 0; s < std::max<std::size_t>(sea_states.size(), 1); ++s) {
        PlannedRun run;
        run.index = static_cast<int>(plan.runs.size());
        run.name = fmt::format("run_{:0{}}", run.index, width);
        run.base_case = base_case;
        run.assignments = sweep.set;
        run.values = variant_values[v];
        for (std::size_t j = 0; j < sweep.variables.size(); ++j)
          run.assignments.push_back({sweep.variables[j].path, number_text(variant_values[v][j]), variant_locations[v][j]});
        if (sweep.scatter) {
          const SeaState& sea = sea_states[s];
          run.values.insert(run.values.end(), {sea.hs, sea.tp});
          run.probability = sea.probability;
          run.assignments.push_back({sweep.scatter->hs_path, number_text(sea.hs), sweep.scatter->hs_location});
          run.assignments.push_back({sweep.scatter->tp_path, number_text(sea.tp), sweep.scatter->tp_location});
        }
        // The resolved text, as load_case makes it (include, then --set in order).
        CaseNode tree = base;
        try {
          for (const std::string& assignment : run.overrides()) apply_override(tree, assignment);
        } catch (const InputError& error) {
          throw error_in_sweep(run, plan.columns, error);
        }
        run.hash = run_hash(to_yaml_text(tree));
        plan.runs.push_back(std::move(run));
      }
    }
  }
  return plan;
}

}  // namespace heavesim
