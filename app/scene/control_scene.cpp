#include "app/scene/control_scene.hpp"

#include <fmt/format.h>

#include "control/analysis/stroke_loop.hpp"
#include "kernel/algorithms/inverse_dynamics.hpp"
#include "kernel/algorithms/joint_forces.hpp"
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

/// Generalized force (nv) of a unit force along the stroke at the current position stage:
/// Q = tau + sum over links of S^T (forces on the link's subtree).
VectorX generalized_force(const Model& model, const Data& data, const AppliedForces& forces) {
  VectorX Q = forces.joint_force;
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    Force subtree = Force::Zero();
    for (int j = i; j < model.links[i].subtree_end; ++j) subtree += forces.external_force_world[j];
    for (int c = 0; c < joint.nv; ++c) Q[joint.v_index + c] += dot(data.motion_subspace_world.col(joint.v_index + c), subtree);
  }
  return Q;
}

/// The force [N] along the stroke that holds the initial configuration at rest against
/// gravity and the loads already in `system` (least squares over the generalized
/// coordinates; for a joint-form stroke, exactly that coordinate's load).
double static_load(const Model& model, Data& data, const MultibodySystem& system, double t0, const VectorX& q0,
                   const VectorX& unit) {
  const VectorX zero = VectorX::Zero(model.nv);
  VectorX needed = rnea(model, data, q0, zero, zero);  // = -(generalized gravity) at rest
  AppliedForces others(model);
  add_joint_element_forces(model, q0, zero, others.joint_force);
  for (const auto& element : system.force_elements()) {
    VectorX z(element->state_size());
    element->initial_state(z);
    element->apply(t0, model, data, z, others);
  }
  needed -= generalized_force(model, data, others);
  return unit.dot(needed) / unit.squaredNorm();
}

PneumaticParameters balanced(const CaseDefinition& definition, const CompensatorDefinition& def, double load,
                             double initial_stroke) {
  PneumaticParameters p = def.pneumatic;
  const double needed = p.atmospheric_pressure + load / p.piston_area;  // at the initial stroke, at rest
  const double volume_ratio = (p.gas_volume + p.piston_area * initial_stroke) / p.gas_volume;
  // p_init = p0 (V0/V)^n without the gas state; p0 (V0/V) at the initial temperature with it.
  p.gas_pressure = needed * std::pow(volume_ratio, p.has_gas_state() ? 1.0 : p.exponent_expansion);
  if (!(p.gas_pressure >= p.atmospheric_pressure))
    throw compensator_error(definition, def.name, "gas_pressure",
                            fmt::format("'balance', which needs {:g} Pa at mid-stroke, below atmospheric: the static "
                                        "load along the stroke is {:g} N (it pulls the stroke out)",
                                        p.gas_pressure, load),
                            "a load that compresses the gas (a weight carried along +axis), or an explicit "
                            "gas_pressure");
  return p;
}

bool same_stroke(const StrokeDefinition& a, const StrokeDefinition& b) {
  return a.joint_form() ? a.joint == b.joint
                        : !b.joint_form() && a.base_body == b.base_body && a.moving_body == b.moving_body;
}

}  // namespace

void add_compensators(const CaseDefinition& definition, const Model& model, MultibodySystem& system, double t0,
                      const VectorX& q0) {
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
      AppliedForces unit_force(model);
      apply_stroke_force(axis, model, data, 1.0, unit_force);
      const VectorX unit = generalized_force(model, data, unit_force);
      const double initial_stroke = stroke_motion(axis, model, data).stroke;
      // Mass seen along the stroke with every other coordinate held: Q^T M Q / |Q|^4
      // (M_jj for a joint-form stroke).
      const double apparent_mass = unit.dot(mass * unit) / std::pow(unit.squaredNorm(), 2);
      Built b{&def, def.pneumatic, def.active, apparent_mass};

      if (def.type == CompensatorDefinition::Type::pneumatic) {
        const EndStops& stops = def.pneumatic.end_stops;
        if (initial_stroke < stops.lower || initial_stroke > stops.upper)
          throw compensator_error(definition, def.name, "end_stops",
                                  fmt::format("an initial stroke of {:g} m, outside the end stops [{:g}, {:g}] m",
                                              initial_stroke, stops.lower, stops.upper),
                                  "an initial state between the end stops");
        if (def.balance_pressure)
          b.pneumatic = balanced(definition, def, static_load(model, data, system, t0, q0, unit), initial_stroke);
        system.add_force_element(std::make_unique<PneumaticCompensator>(def.name, axis, b.pneumatic));
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
        system.add_force_element(std::make_unique<ActiveCompensator>(def.name, axis, p));
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
    const StrokeLoopPoles poles = stroke_loop_poles(active.apparent_mass, elements);
    double scale = 1.0;
    for (const auto& pole : poles.poles) scale = std::max(scale, std::abs(pole));
    // Growth slower than one e-fold in 500 s is not flagged: a linearization across a
    // critically centred valve's null (a kink) resolves no better than that.
    if (poles.largest_real_part > std::max(1e-6 * scale, 2e-3)) {
      std::complex<double> worst = poles.poles.front();
      for (const auto& pole : poles.poles)
        if (pole.real() > worst.real()) worst = pole;
      std::string advice;
      if (active.active.actuator == ActuatorType::force) {
        advice = "e.g. by pole placement on the carried mass M: kp = M w^2, kd = 2 zeta M w, ki = 0.1 w kp "
                 "(offshore-model.md §3.5)";
      } else {
        const HydraulicCylinderParameters& c = active.active.hydraulic.cylinder;
        const double omega_h = std::sqrt(c.bulk_modulus * (c.area_a * c.area_a / c.volume_a + c.area_b * c.area_b / c.volume_b) /
                                         active.apparent_mass);
        advice = fmt::format("for a valve-driven cylinder a position-loop gain kp [1/s] well below 2 zeta_h "
                             "omega_h, with the hydraulic resonance omega_h = {:.3g} rad/s here and its damping "
                             "zeta_h from the valve's null leakage (valve.underlap) and cylinder leakage",
                             omega_h);
      }
      throw compensator_error(
          definition, active.def->name, "controller",
          fmt::format("gains that make the stroke loop unstable: closed-loop pole at {:.4g} {} {:.4g}i 1/s (loop "
                      "linearized at the initial state with the {:.4g} kg carried along the stroke)",
                      worst.real(), worst.imag() < 0 ? "-" : "+", std::abs(worst.imag()), active.apparent_mass),
          "gains with every closed-loop pole in the left half-plane, " + advice);
    }
  }
}

}  // namespace heavesim
