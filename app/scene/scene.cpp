#include "app/scene/scene.hpp"

#include <cmath>

#include <fmt/format.h>

#include "app/scene/contact_scene.hpp"
#include "app/scene/hydro_scene.hpp"
#include "app/scene/run_size.hpp"

#include "app/scene/scene_build_context.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/analysis/kinematic_analysis.hpp"

namespace heavesim {
namespace {

/// Builds the case's force elements of one stage, in declaration order (BuildStage,
/// app/forces/force_kind.hpp).
void build_forces(BuildStage stage, SceneBuildContext& context) {
  for (const ForceDefinition& force : context.definition.forces)
    std::visit(
        [&](const auto& kind) {
          if (kind.stage == stage) kind.build(force.name, context);
        },
        force.kind);
}

/// An over-driven mechanism, found where assembly failed: a dependent group of rows with
/// a driver among them whose residuals disagree (inconsistent_rows). Reported at the
/// driver declared last in the group, naming the rows it fights; nothing when no such
/// group holds a driver.
void reject_over_driven(const CaseDefinition& definition, const Model& model, Data& data) {
  for (const InconsistentRows& group :
       inconsistent_rows(model, data, definition.solver.t_start, definition.solver.integrator.constraint_tolerance)) {
    std::vector<int> rows = group.rows;
    rows.push_back(group.dependent);
    const Constraint* driver = nullptr;
    for (const int row : rows) {
      const Constraint* constraint = constraint_of_row(model, row);
      if (constraint && constraint->is_driver() &&
          (!driver || constraint->first_row > driver->first_row))
        driver = constraint;
    }
    if (!driver) continue;
    std::string fought;
    for (const int row : rows)
      if (constraint_of_row(model, row) != driver)
        fought += (fought.empty() ? "" : ", ") + describe_constraint_row(model, row);
    throw definition.item_error(
        driver->name, "name",
        fmt::format("an over-driven mechanism: driver '{}' prescribes a coordinate that {} already determine, to a "
                    "different value (mismatch {:.3g} m or rad at t = {:g} s)",
                    driver->name, fought, std::abs(group.mismatch), definition.solver.t_start),
        "drivers only on free directions: remove this driver or the one it fights, or drive another coordinate "
        "(`heavesim kinematics` prints the free directions)");
  }
}

/// Newton iterations from the user's state onto Phi = 0, J v = 0 (projection.hpp).
/// A state that does not assemble is bad input: the loop cannot close there.
Assembly assemble(const CaseDefinition& definition, const Model& model, Data& data, VectorX& q, VectorX& v) {
  Assembly assembly;
  const VectorX q_user = q, v_user = v;
  const ProjectionResult result =
      project_to_constraints(model, data, definition.solver.t_start, q, v, definition.solver.integrator.constraint_tolerance, 50);
  assembly.newton_iterations = result.iterations;
  assembly.position_residual = result.position_residual;
  if (!result.converged) {
    reject_over_driven(definition, model, data);
    int worst = 0;
    data.constraint_residual.cwiseAbs().maxCoeff(&worst);
    const std::string row = describe_constraint_row(model, worst);
    const std::string& name = constraint_of_row(model, worst)->name;  // every constraint comes from the case
    const std::string& key_path = definition.item_paths.at(name);
    const SourceLocation location = definition.location_of(key_path + ".name");
    throw InputError(location, key_path,
                     fmt::format("an initial state where {} cannot close: |Phi| = {:.3g} after {} Newton iterations",
                                 row, result.position_residual, result.iterations),
                     fmt::format("initial joint coordinates near a configuration that satisfies every loop "
                                 "(|Phi| <= solver.constraint_tolerance = {:g})",
                                 definition.solver.integrator.constraint_tolerance));
  }
  assembly.largest_position_change = (q - q_user).cwiseAbs().maxCoeff();
  assembly.largest_speed_change = model.nv > 0 ? (v - v_user).cwiseAbs().maxCoeff() : 0.0;
  assembly.rank = analyse_constraint_rank(model, data, definition.solver.t_start);
  return assembly;
}

}  // namespace

Scene build_scene(const CaseDefinition& definition) {
  // Hydro data first: A(inf) of a radiation element is its body's added inertia.
  const HydroData hydro_data = read_hydro_data(definition);
  ModelBuilder builder;
  builder.set_gravity(definition.gravity);
  for (BodyDefinition body : definition.bodies) {
    if (auto it = hydro_data.added_inertia.find(body.name); it != hydro_data.added_inertia.end())
      body.added_inertia = body.added_inertia ? Matrix6(*body.added_inertia + it->second) : it->second;
    builder.add_body(body);
  }
  for (const JointDefinition& joint : definition.joints) builder.add_joint(joint);
  for (const LoopJointDefinition& joint : definition.loop_joints) builder.add_loop_joint(joint);
  for (const DistanceConstraintDefinition& constraint : definition.distance_constraints)
    builder.add_distance_constraint(constraint);
  for (const CouplerDefinition& coupler : definition.couplers) builder.add_coupler(coupler);
  for (const ExpressionConstraintDefinition& constraint : definition.expression_constraints)
    builder.add_expression_constraint(constraint);
  for (const DriverDefinition& driver : definition.drivers) builder.add_driver(driver);
  // Under IDA a joint stop is met by event location: each bound a constraint row that
  // holds while the stop is engaged (kernel/system/joint_stop_events.hpp). The contact
  // integrator steps the stops itself (the `contacts` element).
  if (definition.solver.integrator.method == IntegrationMethod::ida)
    for (const JointStopDefinition& stop : definition.contacts.joint_stops)
      for (const bool lower : {true, false})
        if (const double bound = lower ? stop.lower : stop.upper; std::isfinite(bound))
          builder.add_joint_stop({stop.name + (lower ? ".lower" : ".upper"), stop.joint, bound, lower, stop.restitution});

  Scene scene;
  try {
    scene.model = std::make_shared<const Model>(builder.build());
  } catch (const ModelError& error) {
    // A stop's rows: its item in `contacts` (the contact check says the same of it).
    for (std::size_t s = 0; s < definition.contacts.joint_stops.size(); ++s)
      if (error.item().rfind(definition.contacts.joint_stops[s].name + ".", 0) == 0)
        throw definition.error_at(fmt::format("contacts.joint_stops[{}].{}", s, error.field()), error.found(),
                                  error.expected());
    throw to_input_error(definition, error);
  }
  const Model& model = *scene.model;
  SystemSettings settings;
  settings.method = definition.solver.dynamics;
  settings.projection_tolerance = definition.solver.integrator.constraint_tolerance;
  scene.system = std::make_unique<MultibodySystem>(scene.model, settings);
  SceneBuildContext context(definition, model, *scene.system, scene.summarised, hydro_data);
  context.t_start = definition.solver.t_start;
  build_forces(BuildStage::on_model, context);
  build_forces(BuildStage::hydro, context);

  VectorX q0 = model.neutral_configuration();
  VectorX v0 = VectorX::Zero(model.nv);
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    auto it = definition.initial_states.find(joint.name);
    if (it == definition.initial_states.end()) continue;
    q0.segment(joint.q_index, joint.nq) = it->second.q;
    v0.segment(joint.v_index, joint.nv) = it->second.v;
  }
  // Driven coordinates start on their prescribed motion, so that assembly does not
  // move the other coordinates to meet them.
  for (const Constraint& constraint : model.constraints) {
    const auto* driver = std::get_if<DriverConstraint>(&constraint.kind);
    if (!driver) continue;
    const Joint& joint = model.joints[driver->joint];
    const DriverMotion start = driver->motion(definition.solver.t_start);
    q0[joint.q_index + driver->coordinate] = start.position;
    v0[joint.v_index + driver->coordinate] = start.velocity;
  }
  if (model.has_constraints()) scene.assembly = assemble(definition, model, scene.system->mutable_data(), q0, v0);
  // The elements built on the assembled state read its positions from the system's Data.
  update_positions(model, scene.system->mutable_data(), q0);
  context.set_initial_configuration(q0);
  build_forces(BuildStage::on_assembled, context);
  build_forces(BuildStage::compensators, context);
  build_contacts(definition, *scene.system);
  for (const auto& check : context.after_build) check();
  scene.initial_state = scene.system->initial_state(q0, v0);
  if (definition.initial_static) {
    scene.equilibrium = solve_static_equilibrium(*scene.system, definition.solver.t_start, scene.initial_state,
                                                 definition.equilibrium);
    scene.initial_state = scene.equilibrium->state;
  }
  check_run_size(definition, scene);
  return scene;
}

std::string describe_redundant_rows(const Model& model, const ConstraintRank& rank) {
  std::string text;
  for (int row : rank.redundant_rows) text += (text.empty() ? "" : "; ") + describe_constraint_row(model, row);
  return text;
}

}  // namespace heavesim
