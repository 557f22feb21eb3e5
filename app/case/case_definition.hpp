#pragma once
// A loaded and checked case: everything needed to build and run the scene, in SI
// units and kernel types, plus where each item came from (for later error messages).
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "app/case/contact_definition.hpp"
#include "app/case/hydro_definition.hpp"
#include "app/case/input_error.hpp"
#include "app/forces/force_kinds.hpp"
#include "kernel/algorithms/forward_dynamics.hpp"
#include "kernel/analysis/kinematic_analysis.hpp"
#include "kernel/analysis/static_equilibrium.hpp"
#include "kernel/integrators/integrator.hpp"
#include "kernel/model/model_builder.hpp"
#include "kernel/parameter_error.hpp"

namespace heavesim {

class CaseNode;  // app/case/case_node.hpp

/// Initial joint coordinates q (nq) and speeds v (nv), in the kernel's convention.
struct JointInitialState {
  VectorX q;
  VectorX v;
};

struct SolverSettings {
  IntegratorSettings integrator;
  double t_start = 0.0;  // s
  double t_end = 10.0;   // s
  ForwardDynamicsMethod dynamics = ForwardDynamicsMethod::articulated_body;
  // integrator.constraint_tolerance: largest |Phi| accepted at assembly, after each
  // projection and at the end of an HHT step [m or rad].
};

/// Output intervals of a run from solver.t_start to solver.t_end, the last one ending
/// exactly on t_end (at least 1). The run-size limits keep it far below LONG_MAX.
inline long output_interval_count(const SolverSettings& solver, double output_interval) {
  return std::max(1L, std::lround((solver.t_end - solver.t_start) / output_interval));
}
/// Samples a run records: t_start and the end of every output interval (the result file
/// reserves this many rows; the run-size limits count them).
inline long output_sample_count(const SolverSettings& solver, double output_interval) {
  return output_interval_count(solver, output_interval) + 1;
}

struct OutputSettings {
  double interval = 0.01;  // s between recorded samples
  bool bodies = true;      // /bodies/<name>/position, orientation, velocity
  bool joints = true;      // /joints/<name>/q, qd, qdd
  bool reactions = true;   // /joints/<name>/reaction_force, reaction_moment (+ joint axes)
  bool energy = true;      // /signals/kinetic_energy, potential_energy, total_energy
  bool forces = true;      // /forces/<element>/<channel>: force-element outputs (compensators, hydro)
  /// s: start of the window the summary statistics (compensation efficiency) are taken
  /// over, after transients and wave ramps; default the middle of the record.
  double evaluate_after = 0.0;
};

/// What a run may ask of the machine. Beyond these a case is refused before running
/// (exit code 2, at the key that makes the run large), unless the user allows large runs
/// (`heavesim run/check --allow-large-runs`); beyond `largest_count` it is refused in
/// any case.
struct RunLimits {
  /// Bytes of recorded samples (samples x columns x 8 bytes): a result file that fits in
  /// memory and on disk of an ordinary machine, and that h5py/numpy read in one piece.
  /// The CSV text of the same samples is about three times larger.
  static constexpr double max_output_bytes = 2.0 * 1024 * 1024 * 1024;
  /// Integration steps (fixed-step methods: duration / step; variable-step ones: at
  /// least duration / max_step and one per output sample): at the ~1 us a step of the
  /// smallest model takes, 1e9 steps are about 20 minutes; real models take 10-100x.
  static constexpr double max_steps = 1e9;
  /// Steps or samples no run can do, allowed or not: at 1 ns each, 1e15 take 11 days,
  /// and counts beyond it lose their meaning in the run loop's arithmetic.
  static constexpr double largest_count = 1e15;
  bool allow_large_runs = false;
};

struct CaseDefinition {
  std::string name;
  std::string description;
  std::string source_path;
  std::string resolved_yaml;  // the case after includes and --set, as YAML text

  Vector3 gravity = Vector3(0.0, 0.0, -9.81);
  std::vector<BodyDefinition> bodies;
  std::vector<JointDefinition> joints;
  std::vector<LoopJointDefinition> loop_joints;
  std::vector<DistanceConstraintDefinition> distance_constraints;
  std::vector<CouplerDefinition> couplers;
  std::vector<ExpressionConstraintDefinition> expression_constraints;  // constraints[i] of type expression
  std::vector<DriverDefinition> drivers;
  std::vector<ForceDefinition> forces;              // from forces:, in declaration order (app/forces/)
  ContactDefinition contacts;                       // contacts: (none unless declared)
  WaterDefinition water;                            // environment.water_density, water_depth
  WaveDefinition waves;                             // waves: (none unless declared)
  std::map<std::string, JointInitialState> initial_states;  // by joint name
  SolverSettings solver;
  OutputSettings output;
  KinematicSettings kinematics;  // the `kinematics` section (heavesim kinematics)
  RunLimits limits;
  /// `initial: static`: a run starts from the static equilibrium (the joints' `initial`
  /// values are its starting guess); `given` (default): from the joints' values.
  bool initial_static = false;
  EquilibriumSettings equilibrium;  // the `equilibrium` section (kernel/analysis/static_equilibrium.hpp)

  /// Where every key of the resolved case came from, by key path ("joints[2].axis",
  /// "forces[0].stroke.joint", "waves.hs"): the one source map into which errors found
  /// after loading (model, scene, domain rules) point.
  std::map<std::string, SourceLocation> sources;
  /// The key path of each named item: bodies by name; joints, loop joints, constraints,
  /// drivers and forces (one name space) by name.
  std::map<std::string, std::string> body_paths, item_paths;

  /// The position of `key_path`; for a key the case does not give, that of the nearest
  /// enclosing item (its `name` key, else the item itself); else the case file.
  SourceLocation location_of(const std::string& key_path) const;
  /// An InputError at `key_path` (position from location_of).
  InputError error_at(const std::string& key_path, const std::string& found, const std::string& expected) const;
  /// An InputError at `field` (a key path relative to the item) of the named joint,
  /// loop joint, constraint, driver or force.
  InputError item_error(const std::string& item, const std::string& field, const std::string& found,
                        const std::string& expected) const;
};

/// Loads, composes (includes, --set overrides) and checks a case file. Throws
/// InputError for anything malformed or, unless `allow_large_runs`, too large to run
/// (RunLimits); nothing is run. read_case(resolved_case_tree(path, overrides), path, ...).
CaseDefinition load_case(const std::string& path, const std::vector<std::string>& overrides = {},
                         bool allow_large_runs = false);

/// The case file at `path` with its includes merged and the `--set` overrides applied
/// (app/case/case_merge.hpp); InputError for a malformed file or override.
CaseNode resolved_case_tree(const std::string& path, const std::vector<std::string>& overrides);

/// The checked definition of a resolved case tree; `path` is the case file's (the default
/// of the case's name, and where location_of points when no key matches). Each call reads
/// the tree afresh and changes nothing in it: two definitions of one tree share nothing
/// (each expression has its own workspace), so a run parses its case's YAML once for the
/// two scenes it may build (cli/commands/run_command.cpp).
CaseDefinition read_case(const CaseNode& tree, const std::string& path, bool allow_large_runs);

/// Converts a kernel ModelError into an InputError pointing into the case.
InputError to_input_error(const CaseDefinition& definition, const ModelError& error);

/// Converts a domain ParameterError (kernel/parameter_error.hpp) raised while building
/// the part of the case at `base_path` ("forces[3]", "" for the root) into an InputError
/// at the case key of its field: `base_path.<key>`, where key is
/// key_of_field[field] when listed and the field's own name otherwise.
InputError to_input_error(const CaseDefinition& definition, const std::string& base_path, const ParameterError& error,
                          const std::map<std::string, std::string>& key_of_field = {});

}  // namespace heavesim
