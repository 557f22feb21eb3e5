#pragma once
// A sweep file (docs/sweeps.md) as read: the base case, the overrides every run gets,
// the variables and how they combine, an optional scatter diagram of sea states, and
// the channels whose statistics go into the index. Every value remembers where in the
// sweep file it was written, so that a run's bad value is reported there.
#include <optional>
#include <string>
#include <vector>

#include "app/case/input_error.hpp"
#include "app/sweep/scatter_table.hpp"

namespace heavesim {

enum class Sampling { grid, zip, latin_hypercube };
const char* sampling_name(Sampling sampling);

/// One `--set` assignment and where the sweep file gives it.
struct SweepAssignment {
  std::string path;          // case key path, e.g. parameters.T
  std::string value;         // YAML text of the value
  SourceLocation location;   // in the sweep file
};

struct SweepVariable {
  std::string path;                        // the --set key path (the index names the column after it)
  SourceLocation location;                 // of the variable's `path` key
  std::vector<double> values;              // `values:` or `range:`; empty for `sample:`
  std::vector<SourceLocation> value_locations;  // per value (a range: the range's position)
  std::optional<std::pair<double, double>> sample;  // `sample: {from, to}` (Latin hypercube)
};

struct SweepScatter {
  std::string file;             // as resolved (relative to the sweep file)
  std::string hs_path, tp_path; // where Hs and Tp go in the case
  SourceLocation hs_location, tp_location;
  ScatterTable table;
};

struct SweepDefinition {
  std::string sweep_file;
  /// The cases every variant runs on, resolved against the sweep file's directory: `base`
  /// is one case or a list (e.g. the compensation modes), the outermost loop of the plan.
  std::vector<std::string> base_cases;
  std::vector<SweepAssignment> set;      // `set:` applied to every run, in file order
  std::vector<SweepVariable> variables;  // in file order
  Sampling sampling = Sampling::grid;
  long samples = 0;                      // latin_hypercube
  unsigned long long seed = 1;           // latin_hypercube
  SourceLocation sampling_location;
  std::optional<SweepScatter> scatter;
  std::vector<std::string> statistics;   // channel paths (/joints/td_string/reaction_force)
  double duration = 10800.0;             // s, D of the most probable maxima in the index
};

/// Reads and checks a sweep file: every unknown key, bad value, range or scatter file is
/// an InputError (exit 2) naming the file, line, column and key path.
SweepDefinition read_sweep_file(const std::string& path);

}  // namespace heavesim
