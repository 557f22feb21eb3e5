// S1, S2: static equilibrium (`initial: static`, kernel/analysis/static_equilibrium.hpp)
// against hand statics: the spring-loaded crane's elevation and foot reaction
// (validation/oracles/spring_crane.hpp, the moment balance solved by bisection) and the
// drilling rig's heave offset, stroke, gas pressure and hook loads
// (validation/oracles/rig_statics.hpp). Both are solved to equilibrium.tolerance = 1e-13,
// so the rows' 1e-9 is round-off and finite-difference stiffness (it only steers Newton,
// the residual is exact) far below.
#include <cmath>

#include "app/scene/scene.hpp"
#include "kernel/algorithms/joint_reactions.hpp"
#include "validation/checks/validation_suite.hpp"
#include "validation/oracles/rig_statics.hpp"
#include "validation/oracles/spring_crane.hpp"

namespace heavesim::validation {
namespace {

/// The case's scene at its static equilibrium, the full evaluation (reactions included)
/// left at the rest state.
Scene rest_scene(const std::string& relative_path) {
  const CaseDefinition definition = load_case(project_file(relative_path), {});
  Scene scene = build_scene(definition);
  scene.system->evaluate(definition.solver.t_start, scene.initial_state, true);
  return scene;
}

double channel(const MultibodySystem& system, const std::string& element, const std::string& name, double t,
               const VectorX& y) {
  for (std::size_t e = 0; e < system.force_elements().size(); ++e) {
    const ForceElement& f = *system.force_elements()[e];
    if (f.name() != element) continue;
    std::vector<double> values(f.channels().size());
    f.outputs(t, system.model(), system.data(), y.segment(system.state_offset(e), f.state_size()), values);
    for (std::size_t c = 0; c < values.size(); ++c)
      if (f.channels()[c].name == name) return values[c];
  }
  return std::nan("");
}

}  // namespace

std::vector<ValidationRow> check_s1_spring_crane() {
  const oracle::SpringCrane crane;
  const oracle::SpringCraneEquilibrium expected = oracle::spring_crane_equilibrium(crane, 0.05, 1.2);
  const Scene scene = rest_scene("cases/statics/spring_crane.yaml");
  const Model& model = *scene.model;
  const Joint& foot = model.joints[model.joint_index("foot")];
  const double elevation = scene.initial_state[foot.q_index];
  const JointReaction reaction = joint_reaction(model, scene.system->data(), model.joint_index("foot"));
  const double reaction_error = (reaction.force_world - expected.foot_reaction).norm() / expected.foot_reaction.norm();
  return {
      {"S1", "spring-loaded crane, equilibrium elevation (hand moment balance, bisection)", "elevation, relative",
       std::abs(elevation - expected.elevation) / expected.elevation, 1e-9},
      {"S1", "spring-loaded crane, foot reaction (hand force balance)", "|R - R_hand| / |R_hand|", reaction_error, 1e-9},
      {"S1", "spring-loaded crane, stability", "stable (0) or not (1)",
       scene.equilibrium->stability == EquilibriumStability::stable ? 0.0 : 1.0, 0.0},
  };
}

std::vector<ValidationRow> check_s2_rig_statics() {
  const oracle::RigStatics rig;
  const Scene scene = rest_scene("cases/statics/drilling_rig.yaml");
  const Model& model = *scene.model;
  const MultibodySystem& system = *scene.system;
  const VectorX& y = scene.initial_state;
  const double heave = y[model.joints[model.joint_index("platform_motion")].q_index + 2];
  const double stroke = y[model.joints[model.joint_index("compensator")].q_index];
  const double pressure = channel(system, "passive", "gas_pressure", 0.0, y);
  const double hook = joint_reaction(model, system.data(), model.joint_index("td_string")).force_world.z();
  const double compensator = joint_reaction(model, system.data(), model.joint_index("compensator")).force_world.z();
  return {
      {"S2", "drilling rig at rest: platform heave offset (buoyancy = weight, C33)", "heave, relative",
       relative(heave, rig.heave()), 1e-9},
      {"S2", "drilling rig at rest: compensator stroke (polytropic gas at W_c)", "stroke, relative",
       relative(stroke, rig.stroke()), 1e-9},
      {"S2", "drilling rig at rest: gas pressure (W_c / A + p_atm)", "pressure, relative",
       relative(pressure, rig.balance_pressure()), 1e-9},
      {"S2", "drilling rig at rest: hook load at td_string (string weight in water)", "force, relative",
       relative(hook, rig.string_load()), 1e-9},
      {"S2", "drilling rig at rest: load on the compensator (W_c)", "force, relative",
       relative(compensator, rig.compensator_load()), 1e-9},
  };
}

}  // namespace heavesim::validation
