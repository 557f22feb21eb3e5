// heavesim equilibrium CASE.yaml: the static equilibrium of a case (docs/physics/statics.md),
// printed, written as a one-sample result file and, on request, as a YAML fragment of
// the joints' `initial` values.
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "app/case/case_definition.hpp"
#include "app/output/output_error.hpp"
#include "app/output/recorder.hpp"
#include "app/scene/scene.hpp"
#include "cli/commands/command_support.hpp"
#include "cli/commands/commands.hpp"
#include "cli/commands/result_metadata.hpp"
#include "io/hdf5/hdf5_handle.hpp"
#include "kernel/algorithms/joint_reactions.hpp"

namespace heavesim {
namespace {

/// The units of a joint's raw coordinates q, as the case's `initial.q` takes them.
std::string coordinate_units(const std::string& type) {
  if (type == "revolute") return "rad";
  if (type == "prismatic") return "m";
  if (type == "cylindrical") return "rad, m";
  if (type == "universal") return "rad, rad";
  if (type == "spherical") return "quaternion w, x, y, z";
  if (type == "free") return "m x, y, z; quaternion w, x, y, z";
  return "";
}

std::string list_of(const VectorX& values) {
  std::string text;
  for (int k = 0; k < values.size(); ++k) text += fmt::format("{}{:.15g}", k ? ", " : "", values[k]);
  return text;
}

const char* stability_name(EquilibriumStability stability) {
  switch (stability) {
    case EquilibriumStability::stable: return "stable";
    case EquilibriumStability::neutral: return "neutral";
    case EquilibriumStability::unstable: return "UNSTABLE";
  }
  return "";
}

/// The fragment a case can include (after the case itself, so that it overlays the
/// joints' `initial` by name: case_merge.hpp).
void write_initial_fragment(const std::string& path, const CaseDefinition& definition, const Scene& scene) {
  std::ofstream out(path);
  if (!out) throw OutputError(path, "cannot open the initial-state file for writing", std::strerror(errno));
  const Model& model = *scene.model;
  out << fmt::format("# Static equilibrium of case '{}' at t = {:g} s (heavesim equilibrium).\n"
                     "# Include it after the case: include: [{}, {}]\n"
                     "joints:\n",
                     definition.name, definition.solver.t_start,
                     std::filesystem::path(definition.source_path).filename().string(),
                     std::filesystem::path(path).filename().string());
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    if (joint.nq == 0) continue;
    out << fmt::format("  - name: {}\n    initial: {{q: [{}]}}   # {}\n", joint.name,
                       list_of(scene.initial_state.segment(joint.q_index, joint.nq)),
                       coordinate_units(joint_type_name(joint.type)));
  }
  out.close();
  if (!out) throw OutputError(path, "cannot write the initial-state file", std::strerror(errno));
}

}  // namespace

void print_equilibrium_summary(const Scene& scene) {
  const EquilibriumResult& result = *scene.equilibrium;
  const MultibodySystem& system = *scene.system;
  const Model& model = system.model();
  fmt::print("static equilibrium: {} Newton iterations; residual max |Q + J^T lambda| = {:.3g} of the largest load "
             "({:.6g} N), max |Phi| = {:.3g}, max |dz/dt| = {:.3g}\n",
             result.iterations, result.force_residual, result.load_scale, result.constraint_residual,
             result.rate_residual);
  fmt::print("  stability: {} (lowest w^2 = {:.6g} 1/s^2 on the directions the constraints allow", 
             stability_name(result.stability), result.lowest_squared_frequency);
  if (result.neutral_directions > 0) fmt::print("; {} neutral directions", result.neutral_directions);
  fmt::print(")\n");
  if (result.stability != EquilibriumStability::stable && result.lowest_mode.size() > 0) {
    int at = 0;
    result.lowest_mode.cwiseAbs().maxCoeff(&at);
    fmt::print("  lowest mode mostly along {}\n", describe_velocity_coordinate(model, system.data(), at));
  }
  for (int k : result.held_states)
    fmt::print("  held at its initial value (no rest value): {}\n",
               system.describe_state_component(model.nq + model.nv + k));
}

int equilibrium_command(const EquilibriumOptions& options) {
  hdf5::skip_library_exit_cleanup();
  CaseDefinition definition = load_case(options.case_path, options.overrides);
  definition.initial_static = true;
  const std::string output_path = prepare_result_path(options.output_path, definition.name, "_equilibrium");
  Scene scene = build_scene(definition);
  const Model& model = *scene.model;
  const double t = definition.solver.t_start;

  // The one sample: the rest state with its reactions.
  {
    ResultFile file(output_path, 1);
    write_result_metadata(file, definition);
    write_constraint_summary(file, scene);
    Recorder recorder(definition, scene, file, nullptr);
    recorder.record(t, scene.initial_state);
    recorder.finish();
    const EquilibriumResult& result = *scene.equilibrium;
    file.set_attribute("/", "analysis", std::string("equilibrium"));
    file.set_attribute("/", "equilibrium_iterations", static_cast<long>(result.iterations));
    file.set_attribute("/", "equilibrium_force_residual", result.force_residual);
    file.set_attribute("/", "equilibrium_constraint_residual", result.constraint_residual);
    file.set_attribute("/", "equilibrium_lowest_squared_frequency", result.lowest_squared_frequency);
    file.set_attribute("/", "equilibrium_stability", std::string(stability_name(result.stability)));
    file.mark_complete();
    file.close();
  }
  if (!options.initial_path.empty()) write_initial_fragment(options.initial_path, definition, scene);
  if (options.quiet) return 0;

  // The recorder left the full evaluation (reactions included) at the rest state.
  const MultibodySystem& system = *scene.system;
  fmt::print("case '{}': static equilibrium at t = {:g} s\n", definition.name, t);
  print_equilibrium_summary(scene);
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    const JointReaction reaction = joint_reaction(model, system.data(), i);
    std::string coordinates;
    if (joint.nq > 0) {
      coordinates = fmt::format("q = [{}] ({})", list_of(scene.initial_state.segment(joint.q_index, joint.nq)),
                                coordinate_units(joint_type_name(joint.type)));
      if (joint_type_name(joint.type) == "revolute")
        coordinates += fmt::format(" = {:.6f} deg", scene.initial_state[joint.q_index] * 180.0 / M_PI);
    }
    fmt::print("  joint '{}' ({}): {}\n    reaction force [{:.6g}, {:.6g}, {:.6g}] N, moment [{:.6g}, {:.6g}, "
               "{:.6g}] N m (world axes, parent on child, about the joint origin)\n",
               joint.name, joint_type_name(joint.type), coordinates, reaction.force_world.x(), reaction.force_world.y(),
               reaction.force_world.z(), reaction.moment_world.x(), reaction.moment_world.y(),
               reaction.moment_world.z());
  }
  // Every element's channels that a designer sizes a compensator by.
  std::vector<double> values;
  for (std::size_t e = 0; e < system.force_elements().size(); ++e) {
    const ForceElement& element = *system.force_elements()[e];
    const auto& channels = element.channels();
    if (channels.empty()) continue;
    values.assign(channels.size(), 0.0);
    const int offset = system.state_offset(e);
    element.outputs(t, model, system.data(), scene.initial_state.segment(offset, element.state_size()), values);
    std::string line;
    for (std::size_t c = 0; c < channels.size(); ++c)
      if (channels[c].name == "stroke" || channels[c].name == "gas_pressure" || channels[c].name == "force")
        line += fmt::format("{}{} {:.6g} {}", line.empty() ? "" : ", ", channels[c].name, values[c], channels[c].units);
    if (!line.empty()) fmt::print("  {}: {}\n", element.name(), line);
  }
  fmt::print("  -> {}{}\n", output_path, options.initial_path.empty() ? "" : ", " + options.initial_path);
  return 0;
}

}  // namespace heavesim
