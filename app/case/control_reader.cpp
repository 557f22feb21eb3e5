// The compensator schema (docs/case-format.md, "Compensators"): what can be checked
// without the model is checked here; bodies, joints, the static balance and the
// closed-loop stability are checked when the scene is built (app/scene/control_scene.cpp).
#include "app/case/control_reader.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace heavesim {
namespace {

double positive_or(const NodeReader& item, const std::string& key, double default_value) {
  auto node = item.optional(key);
  return node ? node->positive_number() : default_value;
}

double non_negative_or(const NodeReader& item, const std::string& key, double default_value) {
  auto node = item.optional(key);
  return node ? node->non_negative_number() : default_value;
}

/// An absolute pressure [Pa] that may not be below the atmosphere.
double absolute_pressure(const NodeReader& node, double atmospheric, const std::string& what) {
  const double value = node.number();
  if (!(value >= atmospheric))
    node.fail(fmt::format("{} = {:g} Pa, below atmospheric pressure ({:g} Pa)", what, value, atmospheric),
              "an absolute pressure >= the atmospheric pressure");
  return value;
}

/// {body, point} -> body name and point [m].
std::pair<std::string, Vector3> read_body_point(const NodeReader& reader) {
  reader.expect_section("body_point");
  return {reader["body"].text(), reader.optional("point") ? reader["point"].vector3() : Vector3::Zero()};
}

StrokeDefinition read_stroke(const NodeReader& reader) {
  reader.expect_section("stroke");
  StrokeDefinition stroke;
  stroke.mid_stroke = reader.number_or("mid_stroke", 0.0);
  if (reader.has("joint")) {
    for (const char* key : {"base", "moving", "axis"})
      if (reader.has(key))
        reader[key].fail(fmt::format("'{}' together with 'joint'", key),
                         "either {joint} (a prismatic joint) or {base, moving, axis} (two body points)");
    stroke.joint = reader["joint"].text();
    return stroke;
  }
  if (!reader.has("base") && !reader.has("moving"))
    reader.fail("{joint: <prismatic joint>} or {base: {body, point}, moving: {body, point}, axis: [x, y, z]}");
  std::tie(stroke.base_body, stroke.base_point) = read_body_point(reader["base"]);
  std::tie(stroke.moving_body, stroke.moving_point) = read_body_point(reader["moving"]);
  stroke.axis = reader.optional("axis") ? reader["axis"].unit_vector3() : Vector3::UnitZ();
  return stroke;
}

EndStops read_end_stops(const NodeReader& reader) {
  reader.expect_section("end_stops");
  EndStops stops;
  stops.lower = reader.number_or("lower", stops.lower);
  stops.upper = reader.number_or("upper", stops.upper);
  if (!(stops.lower < stops.upper))
    reader.fail(fmt::format("stroke limits reversed: lower = {:g} m not below upper = {:g} m", stops.lower, stops.upper),
                "lower < upper (stroke from mid-stroke, m)");
  stops.stiffness = positive_or(reader, "stiffness", stops.stiffness);
  stops.damping = non_negative_or(reader, "damping", stops.damping);
  return stops;
}

SealFriction read_friction(const NodeReader& reader) {
  reader.expect_section("seal_friction");
  return {non_negative_or(reader, "coulomb", 0.0), non_negative_or(reader, "viscous", 0.0),
          positive_or(reader, "smoothing_speed", 0.01)};
}

void read_pneumatic(const NodeReader& item, CompensatorDefinition& def) {
  item.expect_section("pneumatic_compensator");
  def.stroke = read_stroke(item["stroke"]);
  PneumaticParameters& p = def.pneumatic;
  p.piston_area = item["piston_area"].positive_number();
  const NodeReader volume = item["gas_volume"];
  p.gas_volume = volume.number();
  if (!(p.gas_volume > 0.0))
    volume.fail(fmt::format("a gas volume of {:g} m^3", p.gas_volume), "a positive volume (m^3, at mid-stroke)");
  p.atmospheric_pressure = positive_or(item, "atmospheric_pressure", p.atmospheric_pressure);
  if (auto pressure = item.optional("gas_pressure");
      pressure && !(pressure->node().is_scalar() && pressure->node().scalar == "balance")) {
    def.balance_pressure = false;
    p.gas_pressure = absolute_pressure(*pressure, p.atmospheric_pressure, "gas pressure");
  }
  if (auto exponent = item.optional("polytropic_exponent")) {
    auto read_exponent = [](const NodeReader& node) {
      const double n = node.number();
      if (!(n >= 1.0 && n <= 5.0 / 3.0))
        node.fail(fmt::format("a polytropic exponent of {:g}", n),
                  "1 <= n <= 5/3 (1 isothermal, 1.4 adiabatic air or nitrogen, 5/3 monatomic)");
      return n;
    };
    if (exponent->node().is_map()) {
      exponent->expect_section("polytropic_exponent");
      p.exponent_compression = read_exponent((*exponent)["compression"]);
      p.exponent_expansion = read_exponent((*exponent)["expansion"]);
    } else {
      p.exponent_compression = p.exponent_expansion = read_exponent(*exponent);
    }
  }
  p.hysteresis_speed = positive_or(item, "hysteresis_speed", p.hysteresis_speed);
  p.initial_temperature = positive_or(item, "initial_temperature", p.initial_temperature);
  if (auto cooling = item.optional("cooling")) {
    cooling->expect_section("cooling");
    p.cooling = GasCooling{(*cooling)["time_constant"].positive_number(),
                           positive_or(*cooling, "wall_temperature", p.initial_temperature)};
  }
  if (p.exponent_compression != p.exponent_expansion && !p.cooling)
    item["polytropic_exponent"].fail(
        "different compression and expansion exponents without 'cooling'",
        "a cooling time constant as well: the net work of every compression-expansion cycle stays in the gas as "
        "heat, and without cooling the mean pressure creeps up cycle after cycle");
  if (auto piping = item.optional("piping")) {
    piping->expect_section("piping");
    p.piping = piping_loss_from_pipe((*piping)["length"].positive_number(), (*piping)["bore"].positive_number(),
                                     non_negative_or(*piping, "viscosity", 0.05), positive_or(*piping, "density", 870.0),
                                     non_negative_or(*piping, "loss_coefficient", 0.0));
  }
  if (auto friction = item.optional("seal_friction")) p.friction = read_friction(*friction);
  p.end_stops = item.optional("end_stops") ? read_end_stops(item["end_stops"]) : EndStops{-3.81, 3.81, 1e8, 1e6};
  // The gas must keep a volume over the whole stroke.
  const double smallest = p.gas_volume + p.piston_area * p.end_stops.lower;
  if (!(smallest > 0.0))
    item["gas_volume"].fail(
        fmt::format("a gas volume of {:g} m^3 at the lower stroke limit (V0 + A s_min = {:g} + {:g} x {:g})", smallest,
                    p.gas_volume, p.piston_area, p.end_stops.lower),
        "V0 + A s_min > 0: more gas volume, a smaller piston or a shorter stroke");
}

void read_force_actuator(const NodeReader& reader, ForceActuatorParameters& a) {
  reader.expect_section("actuator", "force");
  a.time_constant = non_negative_or(reader, "time_constant", a.time_constant);
  a.max_force = positive_or(reader, "max_force", a.max_force);
  // A rate limit needs the lag: ActiveCompensator's rule, checked when the scene builds it.
  if (auto rate = reader.optional("max_rate")) a.max_rate = rate->positive_number();
}

void read_hydraulic_actuator(const NodeReader& reader, CompensatorDefinition& def) {
  reader.expect_section("actuator", "hydraulic");
  HydraulicActuatorParameters& h = def.active.hydraulic;
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
  // Both chambers keep a volume over the cylinder's stroke.
  if (auto range = reader.optional("stroke_range")) {
    range->expect_section("stroke_range");
    def.cylinder_lower = (*range)["lower"].number();
    def.cylinder_upper = (*range)["upper"].number();
    if (!(def.cylinder_lower < def.cylinder_upper))
      range->fail(fmt::format("stroke limits reversed: lower = {:g} m not below upper = {:g} m", def.cylinder_lower,
                              def.cylinder_upper),
                  "lower < upper (stroke from mid-stroke, m)");
  }
  const ChamberVolumes at_lower = chamber_volumes(c, def.cylinder_lower), at_upper = chamber_volumes(c, def.cylinder_upper);
  if (!(at_lower.a > 0.0))
    reader["volume_a"].fail(fmt::format("chamber A volume {:g} m^3 at the lower stroke limit {:g} m", at_lower.a,
                                        def.cylinder_lower),
                            "volume_a + piston_area x lower > 0");
  if (!(at_upper.b > 0.0))
    reader["volume_b"].fail(fmt::format("chamber B volume {:g} m^3 at the upper stroke limit {:g} m", at_upper.b,
                                        def.cylinder_upper),
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

void read_active(const NodeReader& item, CompensatorDefinition& def) {
  item.expect_section("active_compensator");
  def.stroke = read_stroke(item["stroke"]);
  ActiveCompensatorParameters& p = def.active;
  const NodeReader actuator = item["actuator"];
  const std::string kind = actuator["type"].choice({"force", "hydraulic"});
  p.actuator = kind == "force" ? ActuatorType::force : ActuatorType::hydraulic;
  if (p.actuator == ActuatorType::force)
    read_force_actuator(actuator, p.force_actuator);
  else
    read_hydraulic_actuator(actuator, def);

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
}

}  // namespace

void read_compensator(const NodeReader& item, const std::string& type, const std::string& name,
                      CaseDefinition& definition) {
  CompensatorDefinition def;
  def.name = name;
  def.type = type == "pneumatic_compensator" ? CompensatorDefinition::Type::pneumatic
                                             : CompensatorDefinition::Type::active;
  if (def.type == CompensatorDefinition::Type::pneumatic)
    read_pneumatic(item, def);
  else
    read_active(item, def);
  definition.item_paths[name] = item.path();
  definition.compensators.push_back(std::move(def));
}

}  // namespace heavesim
