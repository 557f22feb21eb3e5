#pragma once
// The plan of a sweep: the list of resolved runs, in a fixed order (the index's row
// order, whatever the number of workers or ranks), each with the --set overrides that
// make its case, its values, its probability in the scatter diagram and its hash.
#include <limits>
#include <string>
#include <vector>

#include "app/sweep/sweep_definition.hpp"

namespace heavesim {

struct PlannedRun {
  int index = 0;
  std::string name;                         // run_0000: result runs/<name>.h5, log logs/<name>.log
  std::string base_case;                    // the case file it starts from
  std::vector<double> values;               // per plan column
  std::vector<SweepAssignment> assignments; // `set`, then the variables (and Hs, Tp)
  double probability = std::numeric_limits<double>::quiet_NaN();  // scatter: occurrence / total
  std::string hash;                         // run_hash of its resolved case
  /// The overrides as `heavesim run --set` takes them.
  std::vector<std::string> overrides() const;
  /// "T = 8, a = 2" for messages.
  std::string describe(const std::vector<std::string>& columns) const;
};

struct SweepPlan {
  std::vector<std::string> columns;       // variable key paths in file order, then "Hs", "Tp"
  std::vector<std::string> column_paths;  // the case key path of each column
  std::vector<PlannedRun> runs;
};

/// Every run of the sweep: for each base case (outermost), grid (first variable outermost), zip or Latin hypercube over
/// the variables; with a scatter diagram, every variant at every sea state that occurs
/// (variants outermost). Resolves each run's case (base + set + its values, as `--set`
/// does) to compute its hash; a path or value `--set` refuses is an InputError at the
/// sweep file's position of the value, naming the run.
SweepPlan make_plan(const SweepDefinition& sweep);

/// SHA-256 of the resolved case text and the heavesim version: a run whose result file
/// was written from the same text by the same version need not run again.
std::string run_hash(const std::string& resolved_yaml);
/// The same for a result file written by `version`.
std::string run_hash(const std::string& resolved_yaml, const std::string& version);

/// An InputError raised while loading or building `run`'s case, moved to where the
/// sweep file gives the offending value when it came from one of the run's overrides.
InputError error_in_sweep(const PlannedRun& run, const std::vector<std::string>& columns, const InputError& error);

}  // namespace heavesim
