#include "app/scene/control_scene.hpp"

#include <fmt/format.h>

#include "control/analysis/static_balance.hpp"
#include "control/analysis/stroke_loop.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/algorithms/mass_matrix.hpp"
#include "kernel/model/model_builder.hpp"

namespace heavesim {
namespace {

/// An InputError at forces[name].<field>, at that key's position when known.
InputError compensator_error(const CaseDefinition& definition, const std::string& name, const std::string& field,
                             const std::string& found, const std::string& expected) {
  return definition.item_error(name, field, found, expected);
}

/// The case key (under the compensator's path) of each parameter control/ checks.
const std::map<std::string, std::string>& compensator_keys() {
  static const std::map<std::string, std::string> keys{
      {"joint", "stroke.joint"},
      {"acceleration_feedforward", "controller.acceleration_feedforward"},
      {"max_rate", "actuator.max_rate"}};
  return keys;
}

BodyPoint resolve_point(const CaseDefinition& definition, const Model& model, const std::string& name,
                        const std::string& field, const std::string& body, const Vector3& point) {
  if (body == ModelBuilder::ground_name) return {0, point};
  if (model.link_index(body) < 0)
    throw compensator_error(definition, name, field, "'" + body + "', which is not a body",
                            "'ground' or the name of a body");
  return BodyPoint::on_body(model, body, point);
}

StrokeAxis resolve_stroke(const CaseDefinition& definition, const Model& model, const CompensatorDefinition& def) {
  const StrokeDefinition& stroke = def.stroke;
  if (stroke.joint_form()) {
    const int joint = model.joint_index(stroke.joint);
    if (joint < 1)
      throw compensator_error(definition, def.name, "stroke.joint", "'" + stroke.joint + "', which is not a joint",
                              "the name of a prismatic joint (the stroke is its coordinate)");
    return StrokeAxis::on_joint(model, joint, stroke.mid_stroke);  // ParameterError("joint") unless prismatic
  }
  const BodyPoint base = resolve_point(definition, model, def.name, "stroke.base", stroke.base_body, stroke.base_point);
  const BodyPoint moving =
      resolve_point(definition, model, def.name, "stroke.moving", stroke.moving_body, stroke.moving_point);
  if (base.link == moving.link)
    throw compensator_error(definition, def.name, "stroke.moving", "the same body as the base",
                            "a body that moves relative to the base");
  return StrokeAxis::between(model, base, moving, stroke.axis, stroke.mid_stroke);
}

bool same_stroke(const StrokeDefinition& a, const StrokeDefinition& b) {
  return a.joint_form() ? a.joint == b.joint
                        : !b.joint_form() && a.base_body == b.base_body && a.moving_body == b.moving_body;
}

}  // namespace

void add_compensators(const CaseDefinition& definition, const Model& model, MultibodySystem& system, double t0,
                      const VectorX& q0, SummarisedElements& summarised) {
  if (definition.compensators.empty()) return;
  Data data(model);
  update_positions(model, data, q0);
  update_velocities(model, data, q0, VectorX::Zero(model.nv));
  const MatrixX& mass = mass_matrix(model, data);

  struct Built {
    const CompensatorDefinition* def;
    PneumaticParameters pneumatic;
    ActiveCompensatorParameters active;
    double apparent_mass;
  };
  std::vector<Built> built;
  for (const CompensatorDefinition& def : definition.compensators) {
    try {
      const StrokeAxis axis = resolve_stroke(definition, model, def);
      const VectorX unit = unit_stroke_generalized_force(axis, model, data);
      const double initial_stroke = stroke_motion(axis, model, data).stroke;
      Built b{&def, def.pneumatic, def.active, apparent_stroke_mass(mass, unit)};

      if (def.type == CompensatorDefinition::Type::pneumatic) {
        const EndStops& stops = def.pneumatic.end_stops;
        if (initial_stroke < stops.lower || initial_stroke > stops.upper)
          throw compensator_error(definition, def.name, "end_stops",
                                  fmt::format("an initial stroke of {:g} m, outside the end stops [{:g}, {:g}] m",
                                              initial_stroke, stops.lower, stops.upper),
                                  "an initial state between the end stops");
        if (def.balance_pressure)
          b.pneumatic = balanced_pneumatic(def.pneumatic, static_stroke_load(model, data, system, t0, q0, unit),
                                           initial_stroke);
        summarised.pneumatic_compensators.push_back(
            add_element(system, std::make_unique<PneumaticCompensator>(def.name, axis, b.pneumatic)));
      } else {
        ActiveCompensatorParameters& p = b.active;
        p.controlled_point =
            def.controlled_body
                ? resolve_point(definition, model, def.name, "measurement.controlled_point", *def.controlled_body,
                                def.controlled_point)
                : (axis.joint_form() ? BodyPoint{axis.joint, model.links[axis.joint].X_link_body.translation()}
                                     : axis.moving);
        p.controlled_height = p.controlled_point.position_world(data).z();
        p.base_height = base_motion(axis, model, data).position_world.z();
        p.initial_stroke = initial_stroke;
        summarised.active_compensators.push_back(
            add_element(system, std::make_unique<ActiveCompensator>(def.name, axis, p)));
      }
      built.push_back(b);
    } catch (const ParameterError& error) {
      throw to_input_error(definition, definition.item_paths.at(def.name), error, compensator_keys());
    }
  }

  // Closed-loop stability of every active compensator with the compensators on its stroke.
  for (const Built& active : built) {
    if (active.def->type != CompensatorDefinition::Type::active) continue;
    std::vector<StrokeElementFactory> elements;
    for (const Built& other : built) {
      if (!same_stroke(other.def->stroke, active.def->stroke)) continue;
      if (other.def->type == CompensatorDefinition::Type::pneumatic) {
        elements.push_back([p = other.pneumatic](const Model&, const StrokeAxis& axis) {
          return std::make_unique<PneumaticCompensator>("pneumatic", axis, p);
        });
      } else {
        elements.push_back([p = other.active](const Model& analysis, const StrokeAxis& axis) {
          ActiveCompensatorParameters q = p;
          q.controlled_point = BodyPoint{axis.joint, analysis.links[axis.joint].X_link_body.translation()};
          q.controlled_height = q.base_height = q.initial_stroke = 0.0;
          return std::make_unique<ActiveCompensator>("active", axis, q);
        });
      }
    }
    try {
      check_stroke_loop_stable(stroke_loop_poles(active.apparent_mass, elements), active.active, active.apparent_mass);
    } catch (const ParameterError& error) {
      throw to_input_error(definition, definition.item_paths.at(active.def->name), error, compensator_keys());
    }
  }
}

}  // namespace heavesim
