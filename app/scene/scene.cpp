#include "app/scene/scene.hpp"

#include <fmt/format.h>

#include "app/scene/control_scene.hpp"
#include "app/scene/hydro_scene.hpp"

#include "kernel/algorithms/kinematics.hpp"
#include "kernel/elements/ground_contact.hpp"
#include "kernel/elements/point_force.hpp"
#include "kernel/elements/spring_damper.hpp"

namespace heavesim {
namespace {

InputError force_error(const CaseDefinition& definition, const std::string& force, const std::string& field,
                       const std::string& found, const std::string& expected) {
  return definition.item_error(force, field, found, expected);
}

BodyPoint body_point(const CaseDefinition& definition, const Model& model, const ForceDefinition& force,
                     const std::string& field, const std::string& body, const Vector3& point) {
  if (body == ModelBuilder::ground_name) return {0, point};
  if (model.link_index(body) < 0)
    throw force_error(definition, force.name, field, "'" + body + "', which is not a body",
                      "'ground' or the name of a body");
  return BodyPoint::on_body(model, body, point);
}

void add_force_elements(const CaseDefinition& definition, const Model& model, MultibodySystem& system) {
  for (const ForceDefinition& force : definition.forces) {
    if (force.type == ForceDefinition::Type::ground_contact) continue;  // needs the initial state
    if (force.type == ForceDefinition::Type::point_force) {
      system.add_force_element(std::make_unique<PointForce>(
          force.name, body_point(definition, model, force, "body", force.body_a, force.point_a), force.force_world));
      continue;
    }
    const BodyPoint a = body_point(definition, model, force, "body_a", force.body_a, force.point_a);
    const BodyPoint b = body_point(definition, model, force, "body_b", force.body_b, force.point_b);
    if (a.link == b.link)
      throw force_error(definition, force.name, "body_b", "both ends on '" + force.body_a + "'",
                        "two different bodies");
    system.add_force_element(std::make_unique<SpringDamper>(force.name, a, b, force.spring));
  }
}

/// Ground contacts, once the initial configuration q0 is known: the surface sits
/// preload / k below the point's initial height, so the contact starts carrying the
/// preload (the weight on bit WOB0). Added before the compensators, whose balance
/// pressure then counts the preload.
void add_ground_contacts(const CaseDefinition& definition, const Model& model, MultibodySystem& system,
                         const VectorX& q0, SummarisedElements& summarised) {
  Data& data = system.mutable_data();
  update_positions(model, data, q0);
  for (const ForceDefinition& force : definition.forces) {
    if (force.type != ForceDefinition::Type::ground_contact) continue;
    const BodyPoint point = body_point(definition, model, force, "body", force.body_a, force.point_a);
    if (point.link == 0)
      throw force_error(definition, force.name, "body", "'ground'", "the name of the body that touches the ground");
    GroundContactParameters parameters{force.spring.stiffness, force.spring.damping, 0.0};
    parameters.surface_height = point.position_world(data).z() + force.preload / force.spring.stiffness;
    summarised.ground_contacts.push_back(
        add_element(system, std::make_unique<GroundContact>(force.name, point, parameters)));
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
  assembly.rank = analyse_constraint_rank(model, data);
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
  for (const DriverDefinition& driver : definition.drivers) builder.add_driver(driver);

  Scene scene;
  try {
    scene.model = std::make_shared<const Model>(builder.build());
  } catch (const ModelError& error) {
    throw to_input_error(definition, error);
  }
  const Model& model = *scene.model;
  SystemSettings settings;
  settings.method = definition.solver.dynamics;
  settings.projection_tolerance = definition.solver.integrator.constraint_tolerance;
  scene.system = std::make_unique<MultibodySystem>(scene.model, settings);
  add_force_elements(definition, model, *scene.system);
  add_hydro_elements(definition, hydro_data, model, *scene.system);

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
  add_ground_contacts(definition, model, *scene.system, q0, scene.summarised);
  add_compensators(definition, model, *scene.system, definition.solver.t_start, q0, scene.summarised);
  scene.initial_state = scene.system->initial_state(q0, v0);
  return scene;
}

std::string describe_redundant_rows(const Model& model, const ConstraintRank& rank) {
  std::string text;
  for (int row : rank.redundant_rows) text += (text.empty() ? "" : "; ") + describe_constraint_row(model, row);
  return text;
}

}  // namespace heavesim
