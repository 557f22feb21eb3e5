#pragma once
// Decides which channels a case records and writes them at every output time:
// only what the case asks for is evaluated (reactions cost a product a link after ABA,
// an extra inverse-dynamics pass with loops, CRBA or a prescribed motion).
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "app/case/case_definition.hpp"
#include "app/output/background_worker.hpp"
#include "app/output/compensator_summary.hpp"
#include "app/output/csv_writer.hpp"
#include "app/output/result_file.hpp"
#include "app/output/running_statistics.hpp"
#include "app/scene/scene.hpp"
#include "kernel/algorithms/joint_reactions.hpp"
#include "signal/response_statistics.hpp"

namespace heavesim {

class Recorder {
 public:
  /// A scalar series a command adds to the case's channels (e.g. /kinematics/...): its
  /// value at each sample is read from `value`.
  struct ExtraChannel {
    std::string path;
    std::string units;
    std::string description;
    std::function<double()> value;
  };
  /// `csv` may be null (not written). The recorder's channels are the file's series,
  /// which lay_out_file() creates: the constructor does not touch the file.
  Recorder(const CaseDefinition& definition, Scene& scene, ResultFile& file, CsvWriter* csv,
           const std::vector<ExtraChannel>& extra_channels = {});

  /// Creates the file's series (datasets; units, description and the statistics, NaN until
  /// finish(); the groups' order) and flushes them: the file appears under its name. After
  /// evaluate_on_second_thread() it is the recorder's thread's first job, done while the
  /// caller integrates its first steps (their samples wait in batches meanwhile, evaluated
  /// by the caller when it has a scene: docs/performance.md, "Issue #18, twenty-second
  /// round"), and a failure to write is thrown as a sample's is, by a later record() or
  /// record_queued_samples() (or finish()); else it is done here. Once only, even if it
  /// fails. If not called, the first record(), record_evaluation(),
  /// record_queued_samples() or finish() calls it.
  void lay_out_file();

  /// Evaluates the scene at (t, y) and records one sample of every channel; after
  /// evaluate_on_second_thread(), queues (t, y) for that thread instead (and, with a
  /// caller's scene, may evaluate queued samples on it: see there).
  void record(double t, const VectorX& y);
  /// Why a run of `definition` on `scene` must evaluate its samples in line, on the
  /// integrated scene; "" when they may be evaluated on a second build of the scene, on a
  /// second thread: the process has a second core, the run is long enough to repay a
  /// second build, and every load is a function of (t, y) alone (no element depends on
  /// the evaluations before, ElementDependencies::history; no constraint rows chosen or
  /// switched during the run), so the copy gives the numbers the integrated scene would.
  static std::string why_samples_in_line(const CaseDefinition& definition, const Scene& scene);
  /// From here on, record() copies (t, y) into a batch and a second thread evaluates the
  /// batches and records them, in order, while the caller integrates on
  /// (docs/performance.md, "The samples evaluated beside the integration"). The
  /// recorder's scene must then be its own: a second build of the case that nothing
  /// else evaluates. Up to `evaluation_batches` full batches wait for the thread while it
  /// is busy (on the file's layout or the batches before); the caller waits only when none
  /// is free. With `caller_scene` (the scene the caller integrates, another build of the
  /// same case), the caller meanwhile evaluates the waiting batches' samples on
  /// `caller_scene`, oldest first, glancing at the thread between samples; the thread
  /// records those rows and evaluates the rest when it takes the batches
  /// (docs/performance.md, "Issue #18, twenty-first round" and "twenty-second round");
  /// `caller_scene` is then evaluated inside record() and record_queued_samples(), between
  /// the caller's own uses, at earlier times than its own: the loads must be functions of
  /// (t, y) alone, as why_samples_in_line() requires for the second build. Not with extra
  /// channels. A failure of a sample (NumericalError, OutputError) is thrown by a later
  /// record() or by record_queued_samples(); the samples after it are dropped.
  void evaluate_on_second_thread(Scene* caller_scene = nullptr);
  /// Records every sample record() has queued, throwing a failure among them: call at the
  /// end of a run (finish() does, but a failure there is no longer the run's).
  void record_queued_samples();
  /// Records one sample of the system's current evaluation at (t, y), made by the caller
  /// (a kinematic analysis: MultibodySystem::evaluate_prescribed, with reactions when
  /// needs_reactions()); in line only (not after evaluate_on_second_thread()).
  void record_evaluation(double t, const VectorX& y);
  /// Whether the channels read joint wrenches (an evaluation must compute reactions).
  bool needs_reactions() const { return needs_reactions_; }
  /// Writes per-channel statistics as dataset attributes (whole-record minimum, maximum,
  /// mean, standard_deviation; the evaluation window's stats::statistic_fields()) and the
  /// /summary group.
  void finish();

  long samples() const { return samples_; }
  /// Samples evaluated on the caller's scene (evaluate_on_second_thread(caller_scene)).
  long samples_evaluated_by_caller() const { return samples_evaluated_by_caller_; }
  /// Time [s] of the last sample recorded (in the file and the statistics), NaN before the first.
  double last_sample_time() const { return last_sample_time_; }
  /// Largest value recorded in column 0 of a channel, or NaN if there is no such channel
  /// (after finish(): the statistics take the samples a block at a time).
  double channel_maximum(const std::string& path) const;
  /// Largest |E(t) - E(0)| / max(|E(0)|, max kinetic energy) seen so far (energy channel only).
  double relative_energy_drift() const { return energy_drift_; }
  /// True when only gravity and joint springs do work (no force elements, drivers, joint
  /// limits or joint damping): then E(t) - E(0) is the integration's error. Otherwise it
  /// is also the work of the loads, and /summary names it relative_energy_change.
  bool energy_is_conserved() const { return energy_is_conserved_; }
  /// The load a joint carries, |reaction force| [N] (world axes, parent on child): the
  /// structural figures of a design run. For the hook (the top drive to string joint)
  /// 2 std / mean is the hook-load variation of docs/physics/drilling-rig.md §6.
  struct JointLoad {
    std::string joint;
    double peak = 0.0;           // N, largest over the whole record
    RunningStatistics window;    // N, over the evaluation window t >= output.evaluate_after
  };
  /// Per joint with reactions recorded, in model joint order.
  const std::vector<JointLoad>& joint_loads() const { return joint_loads_; }
  /// Start of the evaluation window [s] (output.evaluate_after).
  double evaluate_after() const { return compensators_.evaluate_after(); }
  const CompensatorSummary& compensators() const { return compensators_; }

 private:
  struct SampleEnergy {
    double kinetic = 0.0, potential = 0.0, total = 0.0;  // J
  };
  /// A scene the samples are evaluated on, and what the channels' fills read of one
  /// evaluation besides its stages: one for the recorder's scene and, when the caller
  /// helps (evaluate_on_second_thread), one for the caller's, used by one thread at a time.
  struct SampleContext {
    MultibodySystem* system = nullptr;
    /// X_world_body of every link (output.bodies; empty otherwise): computed once a sample
    /// for the body's position, orientation and velocity.
    AlignedVector<Transform> body_frames;
    std::vector<JointReaction> reactions;  // of reaction_joints_
    SampleEnergy energy;                   // output.energy
    VectorX phi, constraint_velocity;      // workspaces of the drift channels
  };
  /// Writes a channel's max(columns, 1) values of the sample evaluated on `sample`'s scene
  /// at time t [s] into `out`.
  using FillFunction = std::function<void(SampleContext& sample, double t, double* out)>;
  struct Channel {
    std::string path;
    int columns;  // 0 = scalar series
    std::string units;
    std::string description;
    std::vector<std::string> labels;  // CSV column suffixes
    /// Writes the channel's max(columns, 1) values of a sample; add() moves it to fills_.
    /// Empty for a channel written with others (a force element's outputs).
    FillFunction fill;
    int series = -1;
    /// Over the samples before the evaluation window: with the window's moments
    /// (`response`) they make the whole record's (whole_record_statistics).
    RunningStatistics statistics = {};
    /// Per column, over the evaluation window: the response statistics of
    /// docs/physics/statistics.md (moments, crossings, peaks, extremes, Welch spectrum).
    std::vector<stats::ResponseStatisticsAccumulator> response = {};
    /// Per column, the unit of the CSV header ("[m]"); default: `units` for every column.
    std::vector<std::string> column_units = {};
    /// Where its values lie in a sample's row [values] (the result file's staged sample):
    /// the channels' rows side by side, in the order added.
    long row_offset = 0;
  };
  /// A function that writes a sample's values into the row at `row_offset`: one channel's
  /// (its fill), in add()'s order. One indirect call a channel and sample: a force
  /// element's outputs go straight into the row instead (element_row_offsets_).
  struct Fill {
    FillFunction write;
    long row_offset;
  };
  void add(Channel channel);
  /// The file's series of the channels, in add()'s order, and the groups' order attributes;
  /// then the file's first flush (lay_out_file: here or on the evaluation thread). Out of
  /// line, so that a profile names it (scripts/instruction_share.py).
  [[gnu::noinline]] void create_layout();
  /// lay_out_file() unless it has been called.
  void require_layout() {
    if (!layout_started_) lay_out_file();
  }
  /// The whole record's minimum, maximum, mean and standard deviation of every column:
  /// the samples before the window merged with the window's (Pébay 2008, eq. 3.1).
  static RunningStatistics whole_record_statistics(const Channel& channel);
  /// The last whole block's samples into every channel's statistics (the block worker's
  /// job; the end of the run adds the block being built channel by channel, finish()).
  void add_last_block_statistics(long window_first_row);
  /// `rows` samples of one channel's rows `block` into its statistics (touches that
  /// channel only), the window's from `window_first_row` (-1: none of them). Out of line
  /// so that a profile sees every block's statistics under this one name
  /// (scripts/instruction_share.py): the block worker's and the end of the run's.
  [[gnu::noinline]] static void add_block_statistics(Channel& channel, const double* block, long rows,
                                                     long window_first_row);
  /// The whole block just ended goes to the block worker; the next block starts.
  void hand_over_block();
  /// Throws std::logic_error unless the result file's block holds the recorder's count and its
  /// staged row is the recorder's row (no series but the recorder's).
  void require_file_block_agrees() const;
  /// The evaluation window's statistics of every column of `channel`, column after column,
  /// the fields of statistic_names() (touches that channel only).
  static std::vector<double> response_statistic_values(Channel& channel);
  /// The channel's statistics attributes in the file: the whole record's minimum, maximum,
  /// mean and standard deviation, and the window's `response_values` (finish()).
  void write_statistics(const Channel& channel, const std::vector<double>& response_values);
  /// Whether the channel gets the cycle, extreme-value and spectral statistics (scalar
  /// series but /time, and reactions) or the moments only.
  static bool has_extreme_statistics(const Channel& channel);
  /// The fields of the channel's `statistics` compound attribute.
  static std::vector<std::string> statistic_names(const Channel& channel);
  void define_channels(const CaseDefinition& definition);
  /// Constraint drift always; per-constraint multipliers and wrenches with reactions.
  void define_constraint_channels(const OutputSettings& output);
  /// /drivers/<name>/{force or torque, position, velocity, acceleration} for every driver.
  void define_driver_channels();
  /// /forces/<element>/<channel> for every force element that has output channels.
  void define_element_channels();
  /// The samples queued for the second thread: (t, y) in order, and the rows of the first
  /// `evaluated` of them, which the caller evaluated on its scene while the thread was busy.
  struct SampleBatch {
    std::vector<double> times;
    std::vector<VectorX> states;  // sized once by evaluate_on_second_thread()
    // When the caller helps: evaluation_batch x row_width_ values and evaluation_batch x the
    // compensators' measured values, not zero-filled (a row is read only once written).
    std::unique_ptr<double[]> rows, measured;
    long row_width = 0, measured_width = 0;
    long count = 0;
    long evaluated = 0;
    std::exception_ptr failure;  // of sample `evaluated` on the caller's scene
    double* row(long k) { return rows.get() + k * row_width; }
    double* measured_values(long k) { return measured.get() + k * measured_width; }
  };
  SampleContext make_context(MultibodySystem& system) const;
  /// The sample's row and the compensators' values from `sample`'s scene, evaluated at
  /// (t, y) by the caller of this (kinematic analyses) or by evaluate_row. Out of line, as
  /// commit_row, so that a profile names the two (scripts/instruction_share.py).
  [[gnu::noinline]] void fill_row(SampleContext& sample, double t, const VectorX& y, double* row, double* measured);
  /// Evaluates `sample`'s scene at (t, y) and fills the sample's row from it.
  void evaluate_row(SampleContext& sample, double t, const VectorX& y, double* row, double* measured);
  /// evaluate_row into the file's staged row, then commit_row: one sample in line, or on
  /// the evaluation thread.
  void evaluate_and_record(SampleContext& sample, double t, const VectorX& y);
  /// Records a filled row in sample order: the compensators' and joint loads' running
  /// figures, the energy drift, the file (`row` is or is copied to its staged sample), the CSV.
  [[gnu::noinline]] void commit_row(double t, const double* row, const double* measured);
  /// Records the batch's samples in order, evaluating on `sample`'s scene those the caller
  /// did not (on the evaluation thread, or in line by record_queued_samples()); the batch
  /// is empty after, even when one fails.
  void record_batch(SampleBatch& batch, SampleContext& sample);
  /// The full batch joins the ready ones. While the evaluation thread is busy the caller
  /// evaluates the ready batches' samples (with a scene of its own) and then fills a free
  /// batch if there is one (and no ready sample failed); otherwise (or once the thread is
  /// idle) every ready batch goes to the thread, after the ones before are recorded.
  void hand_over_batch();
  /// The next sample of the oldest ready batch not wholly evaluated, on the caller's scene;
  /// false when there is none (or the caller has no scene, or a ready sample failed).
  bool evaluate_next_ready_sample();
  /// Waits for the batches in hand on the evaluation thread (freed then), and hands it the
  /// ready ones; when that leaves no batch free (all were ready: the thread was on the
  /// layout), waits for those too.
  void start_ready_batches();
  /// settle_evaluation(), then the batches the thread had are free again.
  void free_handed_batches();
  /// evaluation_worker_'s start() or wait(), every batch dropped if it throws (a failure
  /// of the batches in hand, or start()'s job's own when no thread could be made and it
  /// ran here).
  void call_evaluation_worker(void (BackgroundWorker::*call)());
  /// Waits for the batches in hand on the evaluation thread; if one failed, every batch
  /// not recorded is dropped (its samples come after the failure) and the failure thrown.
  void settle_evaluation();
  /// Every batch empty and free, one of them being filled (after a failure).
  void drop_batches();
  int take_free_batch();
  /// After evaluate_on_second_thread(), which sizes the batches.
  bool evaluates_beside() const { return !batches_.empty(); }

  Scene& scene_;
  ResultFile& file_;
  CsvWriter* csv_;
  std::vector<Channel> channels_;
  std::vector<Fill> fills_;
  long row_width_ = 0;          // values in a sample's row: every channel's, side by side
  bool needs_reactions_ = false;
  bool records_energy_ = false;  // output.energy: the energy channels and the drift summary
  std::vector<double> csv_row_;  // the sample's row, kept for the CSV past end_sample()
  /// Where the energies (kinetic, potential, total: side by side) and each recorded
  /// joint's reaction force lie in a sample's row, for the drift and the joint loads.
  long energy_row_offset_ = -1;
  std::vector<long> reaction_force_row_offsets_;
  long block_samples_ = 0;     // samples of the current block, not yet in the statistics
  long window_first_row_ = -1;  // the block's first sample in the evaluation window (-1: none)
  stats::StatisticsOptions response_options_;  // time step = output interval, D = 3 h
  std::int64_t window_samples_ = 0;             // samples expected in the evaluation window
  bool records_bodies_ = false;    // output.bodies: the contexts keep the body frames
  /// The groups' topological order attributes (HDF5 lists a group's members
  /// alphabetically): (group, comma-separated names), written with the layout.
  std::vector<std::pair<std::string, std::string>> group_orders_;
  bool layout_started_ = false;  // lay_out_file() was called (on this thread)
  /// Set before the evaluation thread's first start; its job clears it before laying the
  /// file out (a layout that fails is not tried again).
  bool layout_pending_ = false;
  bool has_extra_channels_ = false;
  long samples_ = 0;
  long samples_evaluated_by_caller_ = 0;
  double last_sample_time_ = std::numeric_limits<double>::quiet_NaN();
  double initial_energy_ = 0.0, max_kinetic_energy_ = 0.0, energy_drift_ = 0.0;
  bool energy_is_conserved_ = false;
  std::vector<JointLoad> joint_loads_;
  std::vector<int> reaction_joints_;
  /// Per force element: where its outputs (one scalar channel each, side by side) lie in
  /// a sample's row, which they are written into; -1 for an element without channels.
  std::vector<long> element_row_offsets_;
  CompensatorSummary compensators_;
  /// The compensators' values of a sample evaluated on the recorder's scene (in line or on
  /// the evaluation thread; the caller's go into its batch).
  std::vector<double> measured_;
  SampleContext own_;             // the recorder's scene
  /// The caller's scene, when it helps evaluate (evaluate_on_second_thread(caller_scene)).
  std::unique_ptr<SampleContext> caller_;
  // The last whole block's statistics, computed on a second thread while the next block's
  // samples are recorded (docs/performance.md, "Recording on two cores"). While it runs it
  // owns the channels' statistics and response accumulators and reads the last whole
  // blocks; this thread touches neither until block_worker_.wait(). Declared last: it is
  // ended first, before the channels it reads go.
  long handed_window_first_row_ = -1;  // the handed-over block's window_first_row_
  BackgroundWorker block_worker_{[this] {
    add_last_block_statistics(handed_window_first_row_);
  }};
  // The samples evaluated beside the integration (evaluate_on_second_thread). The batches
  // pass from free (free_) to being filled (filling_) to ready (ready_, full, in sample
  // order) to in the evaluation thread's hands (handed_, in order) and back to free once
  // that thread has recorded them. This thread touches a handed batch, and the recorder's
  // state but the batches it fills or holds ready, only after settle_evaluation(); it may
  // meanwhile evaluate into a ready batch's rows with caller_, reading of the recorder only
  // what the constructor set (the fills, offsets, reaction joints, the compensators'
  // element indices). 256 samples a batch: a hand-over per ~1 ms of evaluation. Eight
  // batches: while the thread lays the file out (~13-17 ms for the drilling run's 100
  // series) the caller integrates and evaluates them, and waits for the rest of the layout
  // only then; sixteen ran no faster and took 3.5 MiB more (docs/performance.md, "Issue #18,
  // twenty-second round"). A free list taken last in, first out keeps the few batches of a
  // run's steady state the ones in the caches. Declared after block_worker_, which its job
  // starts: ended first.
  static constexpr long evaluation_batch = 256;
  static constexpr int evaluation_batches = 8;
  std::vector<SampleBatch> batches_;
  std::vector<int> free_, ready_, handed_;  // batch indices; capacity for all: no allocation
  int filling_ = -1;
  BackgroundWorker evaluation_worker_{[this] {
    if (std::exchange(layout_pending_, false)) create_layout();
    for (const int batch : handed_) record_batch(batches_[batch], own_);
  }};
};

}  // namespace heavesim
