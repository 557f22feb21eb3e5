// heavesim command line: run, check, validate (see docs/ and README.md).
#include <CLI/CLI.hpp>

#include "cli/commands/command_support.hpp"
#include "cli/commands/commands.hpp"
#include "cli/process_memory.hpp"
#include "app/version.hpp"

int main(int argc, char** argv) {
  using namespace heavesim;
  back_heap_with_huge_pages();
  CLI::App app{"heavesim: offshore heave-compensation simulator (multibody kernel with joint reactions)"};
  app.set_version_flag("--version", std::string(heavesim_version));
  app.require_subcommand(1);

  RunOptions run_options;
  CLI::App* run = app.add_subcommand("run", "run one case and write its HDF5 result file");
  run->add_option("case", run_options.case_path, "case file (YAML)")->required();
  run->add_option("-o,--output", run_options.output_path, "result file (default results/<case name>.h5)");
  run->add_option("--csv", run_options.csv_directory, "also write <case name>.csv into this directory");
  run->add_option("--set", run_options.overrides, "override a case value: key.path=value (repeatable)")
      ->allow_extra_args(false);
  run->add_flag("-q,--quiet", run_options.quiet, "no progress line and no summary");
  const std::string allow_large_help =
      "run a case beyond the run-size limits (2 GiB of output, 1e9 steps; docs/case-format.md)";
  run->add_flag("--allow-large-runs", run_options.allow_large_runs, allow_large_help);

  RunOptions kinematics_options;
  CLI::App* kinematics = app.add_subcommand(
      "kinematics", "kinematic analysis of a driven mechanism: positions, velocities, accelerations, driver forces");
  kinematics->add_option("case", kinematics_options.case_path, "case file (YAML)")->required();
  kinematics->add_option("-o,--output", kinematics_options.output_path, "result file (default results/<case name>.h5)");
  kinematics->add_option("--csv", kinematics_options.csv_directory, "also write <case name>.csv into this directory");
  kinematics->add_option("--set", kinematics_options.overrides, "override a case value: key.path=value (repeatable)")
      ->allow_extra_args(false);
  kinematics->add_flag("-q,--quiet", kinematics_options.quiet, "no progress line and no summary");
  kinematics->add_flag("--allow-large-runs", kinematics_options.allow_large_runs, allow_large_help);

  std::string check_path;
  std::vector<std::string> check_overrides;
  CLI::App* check = app.add_subcommand("check", "load and check a case without running it; print the model");
  check->add_option("case", check_path, "case file (YAML)")->required();
  check->add_option("--set", check_overrides, "override a case value: key.path=value (repeatable)")
      ->allow_extra_args(false);
  bool check_allow_large_runs = false;
  check->add_flag("--allow-large-runs", check_allow_large_runs, allow_large_help);

  EquilibriumOptions equilibrium_options;
  CLI::App* equilibrium = app.add_subcommand("equilibrium", "solve a case's static equilibrium; print and write it");
  equilibrium->add_option("case", equilibrium_options.case_path, "case file (YAML)")->required();
  equilibrium->add_option("-o,--output", equilibrium_options.output_path,
                          "result file (default results/<case name>_equilibrium.h5)");
  equilibrium->add_option("--write-initial", equilibrium_options.initial_path,
                          "also write the joints' initial values at rest as a YAML fragment to include");
  equilibrium->add_option("--set", equilibrium_options.overrides, "override a case value: key.path=value (repeatable)")
      ->allow_extra_args(false);
  equilibrium->add_flag("-q,--quiet", equilibrium_options.quiet, "no summary");

  std::vector<std::string> validation_names;
  bool list_only = false;
  CLI::App* validate = app.add_subcommand("validate", "run the validation suite and print a PASS/FAIL table");
  validate->add_option("names", validation_names, "checks to run (e.g. K1 K3); default all");
  validate->add_flag("--list", list_only, "list the checks without running them");
  int validation_jobs = 1;
  validate->add_option("-j,--jobs", validation_jobs, "checks at once (threads; the table keeps the suite's order)")
      ->check(CLI::Range(1, 1024));

  std::string mksim_path, mksim_case_path;
  CLI::App* import_mksim = app.add_subcommand("import-mksim", "write an MKSim model (.mks) as a heavesim case");
  import_mksim->add_option("model", mksim_path, "MKSim model file")->required();
  import_mksim->add_option("-o,--output", mksim_case_path, "case file to write (YAML)")->required();

  StatsOptions stats_options;
  CLI::App* stats = app.add_subcommand("stats", "response statistics and extremes of a result file's channels");
  stats->add_option("result", stats_options.result_path, "result file (HDF5)")->required();
  stats->add_option("channels", stats_options.channels, "dataset paths, e.g. /joints/hook/reaction_force; default all");
  stats->add_option("--duration", stats_options.duration, "s, duration of the most probable maxima (default 10800 = 3 h)");
  stats->add_option("--after", stats_options.after, "s, start of the window (default the run's output.evaluate_after)");
  stats->add_flag("--json", stats_options.json, "print JSON instead of tables");

  OperabilityOptions operability_options;
  CLI::App* operability = app.add_subcommand("operability", "operability of a sweep over its scatter diagram (docs/operability.md)");
  operability->add_option("index", operability_options.index_path, "the sweep's index file (HDF5)")->required();
  operability->add_option("--criteria", operability_options.criteria_path, "criteria file (YAML)")->required();
  operability->add_option("-o,--output", operability_options.output_directory, "directory of operability.csv/.json/.png");
  operability->add_flag("--json", operability_options.json, "print the JSON summary instead of the table");

  ReportOptions report_options;
  CLI::App* report = app.add_subcommand("report", "one self-contained HTML report of a result file (docs/report.md)");
  report->add_option("result", report_options.result_path, "result file (HDF5)")->required();
  report->add_option("-o,--output", report_options.output_path, "HTML file (default <result stem>_report.html)");
  report->add_option("--duration", report_options.duration, "s, duration of the most probable maxima (default 10800 = 3 h)");
  report->add_option("--from", report_options.from, "s, start of the evaluation window (default the file's own)");
  report->add_option("--validation", report_options.validation_log, "a saved `heavesim validate` output to include");

  SweepOptions sweep_options;
  CLI::App* sweep = app.add_subcommand("sweep", "run a design matrix or a scatter diagram of cases (docs/sweeps.md)");
  sweep->add_option("sweep", sweep_options.sweep_path, "sweep file (YAML)")->required();
  sweep->add_option("-o,--output", sweep_options.output_directory,
                    "directory of the runs, their logs and the index (default results/<sweep name>)");
  sweep->add_option("-j,--jobs", sweep_options.jobs, "runs at once on this machine (worker processes)")
      ->check(CLI::Range(1, 1024));
  sweep->add_flag("--resume,!--no-resume", sweep_options.resume,
                  "skip runs whose result file is complete with the same hash (default), or rerun all");
  sweep->add_flag("-q,--quiet", sweep_options.quiet, "no progress line and no summary");

  RaoOptions rao_options;
  CLI::App* rao = app.add_subcommand("rao", "RAOs per unit wave amplitude: a regular-wave sweep of a case, or H1 from an irregular run (docs/rao.md)");
  rao->add_option("input", rao_options.input, "case file (YAML): a period sweep; or result file (HDF5): H1 from its sea")->required();
  rao->add_option("--periods", rao_options.periods, "s, the sweep's periods: A:STEP:B or T1,T2,...");
  rao->add_option("--amplitude", rao_options.amplitude, "m, the sweep's wave amplitude (default 1)");
  rao->add_option("--channel", rao_options.channels, "surge .. yaw, /bodies/<body>/point(x, y, z)[c] or a result path[column] (repeatable; default the six platform modes)")
      ->allow_extra_args(false);
  rao->add_option("--set", rao_options.overrides, "override a case value: key.path=value (repeatable)")->allow_extra_args(false);
  rao->add_option("--case", rao_options.case_path, "result file only: its case (default the file's case_file)");
  rao->add_option("--segment", rao_options.segment, "s, result file only: the Welch segment of H1 (default about 1/8 of the window)");
  rao->add_option("-j,--jobs", rao_options.jobs, "runs at once on this machine (worker processes)")->check(CLI::Range(1, 1024));
  rao->add_option("-o,--output", rao_options.output_directory, "directory of rao.h5, rao.csv, rao.png and the runs (default results/<input name>_rao)");
  rao->add_flag("!--no-plot", rao_options.plot, "no figure (rao.png)");
  rao->add_flag("-q,--quiet", rao_options.quiet, "no progress line and no table");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }

  // One mapping of errors to exit codes (2 bad input, 3 numerical failure, 1 any other),
  // shared with the sweep's workers and the Python module.
  return exit_code_reporting_errors([&] {
    if (*run) return run_command(run_options);
    if (*kinematics) return kinematics_command(kinematics_options);
    if (*check) return check_command(check_path, check_overrides, check_allow_large_runs);
    if (*equilibrium) return equilibrium_command(equilibrium_options);
    if (*validate) return validate_command(validation_names, list_only, validation_jobs);
    if (*import_mksim) return import_mksim_command(mksim_path, mksim_case_path);
    if (*stats) return stats_command(stats_options);
    if (*operability) return operability_command(operability_options);
    if (*report) return report_command(report_options);
    if (*sweep) return sweep_command(sweep_options);
    if (*rao) return rao_command(rao_options);
    return 1;
  });
}
