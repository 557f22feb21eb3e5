#pragma once
// The heavesim subcommands. Each returns the process exit code:
// 0 success, 2 bad input, 3 numerical failure, 1 anything else.
#include <optional>
#include <string>
#include <vector>

namespace heavesim {

struct RunOptions {
  std::string case_path;
  std::string output_path;             // default results/<case name>.h5
  std::string csv_directory;           // empty: no CSV
  std::vector<std::string> overrides;  // --set key=value
  bool quiet = false;
  bool allow_large_runs = false;       // --allow-large-runs: past RunLimits (app/case/case_definition.hpp)
  /// Whether the recorder may evaluate the samples on a helper thread (where the case
  /// allows: Recorder::why_samples_in_line). Off for the runs of a sweep or RAO that run
  /// side by side: each already has its core, and the thread would only add its cost.
  bool samples_beside = true;
};

int run_command(const RunOptions& options);
/// heavesim kinematics: kinematic analysis over the case's time span (same options as run).
int kinematics_command(const RunOptions& options);
int check_command(const std::string& case_path, const std::vector<std::string>& overrides,
                  bool allow_large_runs = false);
struct Scene;
/// Loops, rank, redundant equations and assembly of a scene (nothing for a tree).
void print_loop_summary(const Scene& scene);

struct EquilibriumOptions {
  std::string case_path;
  std::string output_path;             // default results/<case name>_equilibrium.h5
  std::string initial_path;            // --write-initial: YAML fragment of the joints' initial values
  std::vector<std::string> overrides;  // --set key=value
  bool quiet = false;
};
int equilibrium_command(const EquilibriumOptions& options);
/// The static equilibrium a scene starts from (`initial: static`): residual, stability.
void print_equilibrium_summary(const Scene& scene);

/// heavesim validate: the validation table (docs/validation.md) of the named checks (all
/// if none), `jobs` checks at a time on threads of this process; exit 0 only if every row passes.
int validate_command(const std::vector<std::string>& names, bool list_only, int jobs = 1);

struct StatsOptions {
  std::string result_path;
  std::vector<std::string> channels;  // dataset paths; empty: every time series
  double duration = 10800.0;          // s, D of the most probable maxima (3 h)
  std::optional<double> after;        // s, window start; default the run's output.evaluate_after
  bool json = false;
};
/// heavesim stats: response statistics of a result file's channels (docs/physics/statistics.md).
int stats_command(const StatsOptions& options);

struct OperabilityOptions {
  std::string index_path;        // the sweep's index (HDF5)
  std::string criteria_path;     // --criteria: the limits (YAML)
  std::string output_directory;  // -o: default the index's directory
  bool json = false;
};
/// heavesim operability: runs scripts/operability.py (docs/operability.md); its exit code.
int operability_command(const OperabilityOptions& options);

struct ReportOptions {
  std::string result_path;        // the result file (HDF5)
  std::string output_path;        // -o: default <result stem>_report.html beside it
  double duration = 10800.0;      // s, D of the most probable maxima (3 h, the MPM duration)
  std::optional<double> from;     // s, window start; default the file's statistics_window_start
  std::string validation_log;     // --validation: a saved `heavesim validate` output to include
};
/// heavesim report: runs scripts/report.py (docs/report.md); its exit code.
int report_command(const ReportOptions& options);
struct SweepOptions {
  std::string sweep_path;
  std::string output_directory;  // default results/<sweep file stem>
  int jobs = 1;                  // -j: worker processes (ignored under mpirun: the ranks)
  bool resume = true;            // skip runs already complete with the same hash
  bool quiet = false;
};
/// heavesim sweep: every run of a sweep file, their index (docs/sweeps.md). Exit code 0
/// when every run is complete, 4 when some failed, 2 for a bad sweep file or case, 1 if stopped.
int sweep_command(const SweepOptions& options);

struct RaoOptions {
  std::string input;                   // CASE.yaml: regular-wave period sweep; OUT.h5: H1 from an irregular run
  std::string periods;                 // --periods A:STEP:B or T1,T2,... [s] (sweep only)
  double amplitude = 1.0;              // --amplitude a [m] of the sweep's regular waves
  std::vector<std::string> channels;   // --channel; default the platform's six modes
  std::vector<std::string> overrides;  // --set on the case (each run of a sweep; the H1 reference's case)
  std::string case_path;               // --case: the case of an OUT.h5 (default its case_file attribute)
  double segment = 0.0;                // --segment [s]: H1's Welch segment (0: about an eighth of the window)
  int jobs = 1;                        // -j: runs at once (worker processes)
  std::string output_directory;        // -o: default results/<input stem>_rao
  bool plot = true;                    // --no-plot: no rao.png
  bool quiet = false;
};
/// heavesim rao: RAOs per unit wave amplitude from a regular-wave sweep of a case or from
/// one irregular run (H1), over the frequency-domain RAO (docs/rao.md). Exit 0; 2 bad
/// input; 4 when some runs of a sweep failed; 1 otherwise.
int rao_command(const RaoOptions& options);

/// heavesim import-mksim: the MKSim model at `model_path` written as the case `case_path`.
int import_mksim_command(const std::string& model_path, const std::string& case_path);

}  // namespace heavesim
