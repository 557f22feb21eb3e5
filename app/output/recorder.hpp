#pragma once
// Decides which channels a case records and writes them at every output time:
// only what the case asks for is evaluated (reactions cost one extra pass).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "app/case/case_definition.hpp"
#include "app/output/compensator_summary.hpp"
#include "app/output/csv_writer.hpp"
#include "app/output/result_file.hpp"
#include "app/output/running_statistics.hpp"
#include "app/scene/scene.hpp"

namespace heavesim {

class Recorder {
 public:
  /// `file` and `csv` may be null (not written).
  Recorder(const CaseDefinition& definition, Scene& scene, ResultFile* file, CsvWriter* csv);

  /// Evaluates the scene at (t, y) and records one sample of every channel.
  void record(double t, const VectorX& y);
  /// Writes per-channel statistics as dataset attributes and the /summary group.
  void finish();

  long samples() const { return samples_; }
  /// Largest value recorded in column 0 of a channel, or NaN if there is no such channel.
  double channel_maximum(const std::string& path) const;
  /// Largest |E(t) - E(0)| / max(|E(0)|, max kinetic energy) seen so far (energy channel only).
  double relative_energy_drift() const { return energy_drift_; }
  /// Largest reaction-force magnitude [N] per joint, in model joint order.
  const std::vector<std::pair<std::string, double>>& peak_reactions() const { return peak_reactions_; }
  const CompensatorSummary& compensators() const { return compensators_; }

 private:
  struct Channel {
    std::string path;
    int columns;  // 0 = scalar series
    std::string units;
    std::string description;
    std::vector<std::string> labels;  // CSV column suffixes
    std::function<void(double t, double* out)> fill;
    int series = -1;
    RunningStatistics statistics = {};
  };
  void add(Channel channel);
  void define_channels(const CaseDefinition& definition);
  /// Constraint drift always; per-constraint multipliers and wrenches with reactions.
  void define_constraint_channels(const OutputSettings& output);
  /// /forces/<element>/<channel> for every force element that has output channels.
  void define_element_channels();

  Scene& scene_;
  ResultFile* file_;
  CsvWriter* csv_;
  std::vector<Channel> channels_;
  bool needs_reactions_ = false;
  std::vector<double> row_, csv_row_;
  VectorX phi_, constraint_velocity_;  // workspaces of the drift channels
  long samples_ = 0;
  double initial_energy_ = 0.0, max_kinetic_energy_ = 0.0, energy_drift_ = 0.0;
  std::vector<std::pair<std::string, double>> peak_reactions_;
  std::vector<int> reaction_joints_;
  std::vector<std::vector<double>> element_values_;  // per force element, its outputs at this sample
  CompensatorSummary compensators_;
};

}  // namespace heavesim
