#include <algorithm>

#include <fmt/format.h>

#include "app/case/case_definition.hpp"
#include "app/output/recorder.hpp"
#include "cli/commands/commands.hpp"
#include "app/scene/scene.hpp"

namespace heavesim {

int check_command(const std::string& case_path, const std::vector<std::string>& overrides, bool allow_large_runs) {
  const CaseDefinition definition = load_case(case_path, overrides, allow_large_runs);
  const Scene scene = build_scene(definition);
  const Model& model = *scene.model;

  fmt::print("case '{}' ({})\n", definition.name, case_path);
  if (!definition.description.empty()) fmt::print("  {}\n", definition.description);
  const auto stops = std::count_if(model.constraints.begin(), model.constraints.end(),
                                   [](const Constraint& constraint) { return constraint.is_unilateral(); });
  fmt::print("model: {} bodies, {} joints, {} degrees of freedom (nq = {}, nv = {}), {} loop constraints{}, "
             "total mass {:.6g} kg\n",
             model.num_links() - 1, model.num_links() - 1, model.nv, model.nq, model.nv,
             model.constraints.size() - stops, stops ? fmt::format(" and {} joint-stop bounds", stops) : "",
             model.total_mass());
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    const Link& link = model.links[i];
    fmt::print("  joint {:<16} {:<11} {:>12} -> {:<16} dof {}{}{}   body mass {:.6g} kg\n", joint.name,
               joint_type_name(joint.type), model.links[joint.parent].name, link.name, joint.nv,
               joint.spring ? ", spring-damper" : "", joint.limits ? ", limits" : "", link.inertia.mass());
  }
  print_loop_summary(scene);
  fmt::print("forces: gravity [{:g}, {:g}, {:g}] m/s^2", model.gravity.x(), model.gravity.y(), model.gravity.z());
  int springs = 0, limits = 0;
  for (int i = 1; i < model.num_links(); ++i) {
    springs += model.joints[i].spring.has_value();
    limits += model.joints[i].limits.has_value();
  }
  if (springs) fmt::print("; {} joint spring-dampers", springs);
  if (limits) fmt::print("; {} joint limits", limits);
  fmt::print("; {} force elements\n", scene.system->force_elements().size());
  for (const auto& element : scene.system->force_elements())
    if (element->state_size() > 0 || !element->channels().empty())
      fmt::print("  force element {}: {} internal states, {} output channels\n", element->name(), element->state_size(),
                 element->channels().size());

  const SolverSettings& solver = definition.solver;
  const IntegratorSettings& integrator = solver.integrator;
  fmt::print("solver: {} ", integration_method_name(integrator.method));
  if (is_fixed_step(integrator.method))
    fmt::print("step {:g} s", integrator.step);
  else
    fmt::print("rtol {:g}, atol {:g}", integrator.relative_tolerance, integrator.absolute_tolerance);
  fmt::print(", t = {:g} .. {:g} s, forward dynamics by {}\n", solver.t_start, solver.t_end,
             solver.dynamics == ForwardDynamicsMethod::articulated_body ? "ABA" : "CRBA + Cholesky");
  const OutputSettings& output = definition.output;
  const char* reactions = scene.system->reactions_from_articulated_pass()
                              ? " reactions (from each sample's articulated-body pass)"
                              : " reactions (one inverse-dynamics pass per sample)";
  fmt::print("outputs every {:g} s:{}{}{}{}\n", output.interval, output.bodies ? " bodies" : "",
             output.joints ? " joints" : "", output.reactions ? reactions : "", output.energy ? " energy" : "");
  const std::string in_line = Recorder::why_samples_in_line(definition, scene);
  fmt::print("  samples evaluated {}\n", in_line.empty() ? "beside the integration, on a second build of the scene "
                                                           "(a thread of their own, helped by the integrating one; the result file "
                                                           "laid out there while the first steps run)"
                                                         : "in line: " + in_line);
  fmt::print("state size {}: evaluated per step: kinematics, {}, {}\n", scene.system->size(),
             integrator.method == IntegrationMethod::contact
                 ? "RNEA bias, CRBA and its tree-sparse L^T L, one complementarity problem of impulses over the "
                   "contact points, stops and constraints"
             : model.has_constraints() ? "CRBA + constrained KKT solve (projection after explicit steps; IDA: "
                                         "GGL index-2 residual, one RNEA pass)"
             : solver.dynamics == ForwardDynamicsMethod::articulated_body ? "ABA"
                                                                          : "CRBA + RNEA",
             springs + limits ? "joint elements" : "no joint elements");
  return 0;
}

}  // namespace heavesim
