#include "app/forces/active_compensator.hpp"

#include <fmt/format.h>

#include "app/scene/scene_build_context.hpp"
#include "control/analysis/static_balance.hpp"

namespace heavesim {
namespace {

constexpr KeySpec active_keys[] = {
    {"name", "text", "–", "required", "unique"},
    {"type", "choice", "–", "required", "active_compensator"},
    {"description", "text", "–", "–", "free text"},
    {"stroke", "map", "–", "required", "where it acts"},
    {"actuator", "map", "–", "required", "force or hydraulic actuator"},
    {"controller", "map", "–", "required", "PID and feed-forward"},
    {"measurement", "map", "–", "none", "controlled point or MRU"},
};

constexpr KeySpec actuator_keys[] = {
    {"type", "choice", "–", "required", "force or hydraulic"},
    {"time_constant", "number", "s", "0.1", "first-order lag", "force"},
    {"max_force", "number", "N", "3.9e5", "saturation", "force"},
    {"max_rate", "number", "N/s", "none", "rate limit", "force"},
    {"piston_area", "number", "m²", "required", "A_A", "hydraulic"},
    {"annulus_area", "number", "m²", "required", "A_B", "hydraulic"},
    {"volume_a", "number", "m³", "required", "chamber A volume at mid-stroke", "hydraulic"},
    {"volume_b", "number", "m³", "required", "chamber B volume at mid-stroke", "hydraulic"},
    {"stroke_range", "map", "m", "`{lower: 0, upper: 0}`", "the cylinder's stroke", "hydraulic"},
    {"bulk_modulus", "number", "Pa", "1e9", "effective beta", "hydraulic"},
    {"internal_leakage", "number", "m³/(s·Pa)", "0", "cross-piston leakage", "hydraulic"},
    {"external_leakage", "number", "m³/(s·Pa)", "0", "leakage to tank", "hydraulic"},
    {"atmospheric_pressure", "number", "Pa", "101325", "on the rod cross-section", "hydraulic"},
    {"supply_pressure", "number", "Pa", "required", "constant supply pressure", "hydraulic"},
    {"tank_pressure", "number", "Pa", "2e5", "return pressure", "hydraulic"},
    {"initial_pressures", "list", "Pa", "zero force, p_A + p_B = p_S", "[p_A, p_B]", "hydraulic"},
    {"seal_friction", "map", "–", "none", "as for the pneumatic compensator", "hydraulic"},
    {"valve", "map", "–", "required", "servo valve", "hydraulic"},
    {"max_speed", "number", "m/s", "K √((p_S − p_T)/2) / A_A", "largest stroke speed asked for", "hydraulic"},
};

constexpr KeySpec stroke_range_keys[] = {
    {"lower", "number", "m", "required", "lower end of the cylinder stroke"},
    {"upper", "number", "m", "required", "upper end (> lower)"},
};

constexpr KeySpec valve_keys[] = {
    {"rated_flow", "number", "m³/s", "required", "Q_N at full opening and the rated drop"},
    {"rated_pressure_drop", "number", "Pa", "3.5e6", "Δp_N per land"},
    {"natural_frequency", "number", "rad/s", "2π·30", "ω_v of the spool"},
    {"damping", "number", "–", "0.7", "ζ_v of the spool"},
    {"transition_pressure", "number", "Pa", "1e5", "laminar region of the orifice law"},
    {"underlap", "number", "–", "0", "opening of every land at null, 0 ≤ x_u < 1"},
};

constexpr KeySpec controller_keys[] = {
    {"kp", "number", "N/m / 1/s", "0", "proportional gain"},
    {"ki", "number", "N/(m·s) / 1/s²", "0", "integral gain"},
    {"kd", "number", "N·s/m / –", "0", "derivative gain"},
    {"tracking_time", "number", "s", "√(kd/ki), or kp/ki", "anti-windup time constant"},
    {"velocity_feedforward", "number", "N·s/m / –", "0", "K_v"},
    {"acceleration_feedforward", "number", "N·s²/m / s", "0", "K_a; needs measurement.mru"},
    {"centring_time", "number", "s", "none", "stroke centring time constant"},
    {"centre_stroke", "number", "m", "0", "s_c"},
};

constexpr KeySpec measurement_keys[] = {
    {"controlled_point", "map", "–", "the moving side (joint form: the child body's reference point)",
     "the point whose heave is held"},
    {"mru", "map", "–", "none", "measure through an MRU"},
};

constexpr KeySpec mru_keys[] = {
    {"corner_period", "number", "s", "100", "T_c of the high-pass filter"},
    {"damping", "number", "–", "0.7071", "ζ of the filter"},
    {"lag", "number", "s", "0.01", "τ of the output lag"},
};

void read_force_actuator(const NodeReader& reader, ForceActuatorParameters& a) {
  reader.expect_section("actuator", "force");
  a.time_constant = non_negative_or(reader, "time_constant", a.time_constant);
  a.max_force = positive_or(reader, "max_force", a.max_force);
  // A rate limit needs the lag: ActiveCompensator's rule, checked when the scene builds it.
  if (auto rate = reader.optional("max_rate")) a.max_rate = rate->positive_number();
}

void read_hydraulic_actuator(const NodeReader& reader, HydraulicActuatorParameters& h) {
  reader.expect_section("actuator", "hydraulic");
  HydraulicCylinderParameters& c = h.cylinder;
  c.area_a = reader["piston_area"].positive_number();
  c.area_b = reader["annulus_area"].positive_number();
  for (auto [key, value] : {std::pair{"volume_a", &c.volume_a}, std::pair{"volume_b", &c.volume_b}}) {
    const NodeReader node = reader[key];
    *value = node.number();
    if (!(*value > 0.0)) node.fail(fmt::format("a chamber volume of {:g} m^3", *value), "a positive volume (m^3, at mid-stroke)");
  }
  c.bulk_modulus = positive_or(reader, "bulk_modulus", c.bulk_modulus);
  c.internal_leakage = non_negative_or(reader, "internal_leakage", 0.0);
  c.external_leakage = non_negative_or(reader, "external_leakage", 0.0);
  c.atmospheric_pressure = positive_or(reader, "atmospheric_pressure", c.atmospheric_pressure);
  if (auto friction = reader.optional("seal_friction")) c.friction = read_friction(*friction);
  if (auto speed = reader.optional("max_speed")) h.max_speed = speed->positive_number();
  h.supply.tank_pressure = reader.optional("tank_pressure")
                               ? absolute_pressure(reader["tank_pressure"], c.atmospheric_pressure, "tank pressure")
                               : h.supply.tank_pressure;
  const NodeReader supply = reader["supply_pressure"];
  h.supply.supply_pressure = absolute_pressure(supply, c.atmospheric_pressure, "supply pressure");
  if (!(h.supply.supply_pressure > h.supply.tank_pressure))
    supply.fail(fmt::format("a supply pressure of {:g} Pa, not above the tank pressure {:g} Pa",
                            h.supply.supply_pressure, h.supply.tank_pressure),
                "supply_pressure > tank_pressure");
  if (auto initial = reader.optional("initial_pressures")) {
    const std::vector<double> values = initial->numbers();
    if (values.size() != 2) initial->fail("[p_A, p_B] (Pa, absolute)");
    for (double value : values)
      if (!(value >= 0.0)) initial->fail(fmt::format("a negative pressure {:g} Pa", value), "absolute pressures >= 0");
    h.initial_pressure_a = values[0];
    h.initial_pressure_b = values[1];
  }
  // Both chambers keep a volume over the cylinder's stroke range [m] (checked here only).
  double cylinder_lower = 0.0, cylinder_upper = 0.0;
  if (auto range = reader.optional("stroke_range")) {
    range->expect_section("stroke_range");
    cylinder_lower = (*range)["lower"].number();
    cylinder_upper = (*range)["upper"].number();
    if (!(cylinder_lower < cylinder_upper))
      range->fail(fmt::format("stroke limits reversed: lower = {:g} m not below upper = {:g} m", cylinder_lower,
                              cylinder_upper),
                  "lower < upper (stroke from mid-stroke, m)");
  }
  const ChamberVolumes at_lower = chamber_volumes(c, cylinder_lower), at_upper = chamber_volumes(c, cylinder_upper);
  if (!(at_lower.a > 0.0))
    reader["volume_a"].fail(fmt::format("chamber A volume {:g} m^3 at the lower stroke limit {:g} m", at_lower.a,
                                        cylinder_lower),
                            "volume_a + piston_area x lower > 0");
  if (!(at_upper.b > 0.0))
    reader["volume_b"].fail(fmt::format("chamber B volume {:g} m^3 at the upper stroke limit {:g} m", at_upper.b,
                                        cylinder_upper),
                            "volume_b - annulus_area x upper > 0");
  ServoValveParameters& v = h.valve;
  const NodeReader valve = reader["valve"];
  valve.expect_section("valve");
  v.rated_flow = valve["rated_flow"].positive_number();
  v.rated_pressure_drop = positive_or(valve, "rated_pressure_drop", v.rated_pressure_drop);
  v.natural_frequency = positive_or(valve, "natural_frequency", v.natural_frequency);
  v.damping = positive_or(valve, "damping", v.damping);
  v.transition_pressure = positive_or(valve, "transition_pressure", v.transition_pressure);
  v.underlap = non_negative_or(valve, "underlap", 0.0);
  if (v.underlap >= 1.0) valve["underlap"].fail("an underlap of a full opening or more", "0 <= underlap < 1");
}

}  // namespace

std::span<const KeySpec> ActiveCompensatorDefinition::keys() { return active_keys; }

std::span<const SchemaSection> ActiveCompensatorDefinition::sub_sections() {
  static const SchemaSection sections[] = {
      {"stroke", stroke_keys()},
      {"body_point", body_point_keys()},
      {"actuator", actuator_keys},
      {"stroke_range", stroke_range_keys},
      {"seal_friction", seal_friction_keys()},
      {"valve", valve_keys},
      {"controller", controller_keys},
      {"measurement", measurement_keys},
      {"mru", mru_keys},
  };
  return sections;
}

ActiveCompensatorDefinition ActiveCompensatorDefinition::read(const NodeReader& item, const CaseDefinition&) {
  ActiveCompensatorDefinition def;
  item.expect_section("active_compensator");
  def.stroke = read_stroke(item["stroke"]);
  ActiveCompensatorParameters& p = def.parameters;
  const NodeReader actuator = item["actuator"];
  const std::string kind = actuator["type"].choice({"force", "hydraulic"});
  p.actuator = kind == "force" ? ActuatorType::force : ActuatorType::hydraulic;
  if (p.actuator == ActuatorType::force)
    read_force_actuator(actuator, p.force_actuator);
  else
    read_hydraulic_actuator(actuator, p.hydraulic);

  const NodeReader controller = item["controller"];
  controller.expect_section("controller");
  p.gains.proportional = non_negative_or(controller, "kp", 0.0);
  p.gains.integral = non_negative_or(controller, "ki", 0.0);
  p.gains.derivative = non_negative_or(controller, "kd", 0.0);
  p.gains.tracking_time = positive_or(controller, "tracking_time", 0.0);
  p.velocity_feedforward = controller.number_or("velocity_feedforward", 0.0);
  p.acceleration_feedforward = controller.number_or("acceleration_feedforward", 0.0);
  p.centring_time = positive_or(controller, "centring_time", 0.0);
  p.centre_stroke = controller.number_or("centre_stroke", 0.0);

  if (auto measurement = item.optional("measurement")) {
    measurement->expect_section("measurement");
    if (auto point = measurement->optional("controlled_point")) {
      auto [body, position] = read_body_point(*point);
      def.controlled_body = body;
      def.controlled_point = position;
    }
    if (auto mru = measurement->optional("mru")) {
      mru->expect_section("mru");
      p.mru = MruParameters{};
      p.mru->corner_period = positive_or(*mru, "corner_period", p.mru->corner_period);
      p.mru->damping = positive_or(*mru, "damping", p.mru->damping);
      p.mru->lag = positive_or(*mru, "lag", p.mru->lag);
      if (def.controlled_body)
        (*measurement)["controlled_point"].fail(
            "a controlled point together with 'mru'",
            "one of them: with an MRU the controlled position is the MRU heave at the stroke base plus the stroke");
    }
  }
  // Acceleration feed-forward needs the MRU: ActiveCompensator's rule, checked when the
  // scene builds it.
  return def;
}

void ActiveCompensatorDefinition::build(const std::string& name, SceneBuildContext& context) const {
  const Model& model = context.model;
  SceneBuildContext::InitialState& initial = context.initial_state();
  Data& data = initial.data;
  const auto parameter_error = [&](const ParameterError& error) {
    return to_input_error(context.definition, context.definition.item_paths.at(name), error, compensator_keys());
  };
  try {
    const StrokeAxis axis = resolve_stroke(context, name, stroke);
    const VectorX unit = unit_stroke_generalized_force(axis, model, data);
    const double initial_stroke = stroke_motion(axis, model, data).stroke;
    const double apparent_mass = apparent_stroke_mass(*initial.mass_matrix, unit);
    ActiveCompensatorParameters p = parameters;
    p.controlled_point =
        controlled_body
            ? context.body_point(name, "measurement.controlled_point", *controlled_body, controlled_point)
            : (axis.joint_form() ? BodyPoint{axis.joint, model.links[axis.joint].X_link_body.translation()} : axis.moving);
    p.controlled_height = p.controlled_point.position_world(data).z();
    p.base_height = base_motion(axis, model, data).position_world.z();
    p.initial_stroke = initial_stroke;
    context.summarised.active_compensators.push_back(
        add_element(context.system, std::make_unique<ActiveCompensator>(name, axis, p)));
    context.compensators_on_strokes.push_back({&stroke, [p](const Model& analysis, const StrokeAxis& analysis_axis) {
                                                 ActiveCompensatorParameters q = p;
                                                 q.controlled_point = BodyPoint{
                                                     analysis_axis.joint,
                                                     analysis.links[analysis_axis.joint].X_link_body.translation()};
                                                 q.controlled_height = q.base_height = q.initial_stroke = 0.0;
                                                 return std::make_unique<ActiveCompensator>("active", analysis_axis, q);
                                               }});
    // Closed-loop stability with every compensator on this stroke, once all are built.
    context.after_build.push_back([this, &context, p, apparent_mass, parameter_error] {
      std::vector<StrokeElementFactory> elements;
      for (const CompensatorOnStroke& other : context.compensators_on_strokes)
        if (other.stroke->same_as(stroke)) elements.push_back(other.analysis_element);
      try {
        check_stroke_loop_stable(stroke_loop_poles(apparent_mass, elements), p, apparent_mass);
      } catch (const ParameterError& error) {
        throw parameter_error(error);
      }
    });
  } catch (const ParameterError& error) {
    throw parameter_error(error);
  }
}

}  // namespace heavesim
