#include "app/forces/pneumatic_compensator.hpp"

#include <fmt/format.h>

#include "app/scene/scene_build_context.hpp"
#include "control/analysis/static_balance.hpp"

namespace heavesim {
namespace {

constexpr KeySpec pneumatic_keys[] = {
    {"name", "text", "–", "required", "unique"},
    {"type", "choice", "–", "required", "pneumatic_compensator"},
    {"description", "text", "–", "–", "free text"},
    {"stroke", "map", "–", "required", "where it acts"},
    {"piston_area", "number", "m²", "required", "A"},
    {"gas_volume", "number", "m³", "required", "V0 at mid-stroke"},
    {"gas_pressure", "number or balance", "Pa", "`balance`", "absolute gas pressure at mid-stroke"},
    {"atmospheric_pressure", "number", "Pa", "101325", "on the rod side"},
    {"polytropic_exponent", "number or map", "–", "1.4", "n, or compression and expansion"},
    {"hysteresis_speed", "number", "m/s", "0.01", "width of the n_c/n_e switch"},
    {"initial_temperature", "number", "K", "288.15", "T0"},
    {"cooling", "map", "–", "none", "Newton cooling to the vessel walls"},
    {"piping", "map", "–", "none", "pipe losses"},
    {"seal_friction", "map", "–", "none", "Coulomb and viscous seal friction"},
    {"end_stops", "map", "–", "`{lower: -3.81, upper: 3.81, stiffness: 1e8, damping: 1e6}`", "one-sided end stops"},
};

constexpr KeySpec polytropic_exponent_keys[] = {
    {"compression", "number", "–", "required", "n_c, 1 ≤ n ≤ 5/3"},
    {"expansion", "number", "–", "required", "n_e, 1 ≤ n ≤ 5/3"},
};

constexpr KeySpec end_stops_keys[] = {
    {"lower", "number", "m", "none", "stroke of the lower stop"},
    {"upper", "number", "m", "none", "stroke of the upper stop (> lower)"},
    {"stiffness", "number", "N/m", "1e8", "stop stiffness (> 0)"},
    {"damping", "number", "N·s/m", "1e6", "stop damping (≥ 0)"},
};

constexpr KeySpec cooling_keys[] = {
    {"time_constant", "number", "s", "required", "τ of Newton cooling"},
    {"wall_temperature", "number", "K", "`initial_temperature`", "T_wall"},
};

constexpr KeySpec piping_keys[] = {
    {"length", "number", "m", "required", "L"},
    {"bore", "number", "m", "required", "d"},
    {"viscosity", "number", "Pa·s", "0.05", "μ"},
    {"density", "number", "kg/m³", "870", "ρ of the oil"},
    {"loss_coefficient", "number", "–", "0", "ζ of the fittings"},
};

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

}  // namespace

std::span<const KeySpec> PneumaticCompensatorDefinition::keys() { return pneumatic_keys; }

std::span<const SchemaSection> PneumaticCompensatorDefinition::sub_sections() {
  static const SchemaSection sections[] = {
      {"stroke", stroke_keys()},
      {"body_point", body_point_keys()},
      {"polytropic_exponent", polytropic_exponent_keys},
      {"end_stops", end_stops_keys},
      {"seal_friction", seal_friction_keys()},
      {"cooling", cooling_keys},
      {"piping", piping_keys},
  };
  return sections;
}

PneumaticCompensatorDefinition PneumaticCompensatorDefinition::read(const NodeReader& item, const CaseDefinition&) {
  PneumaticCompensatorDefinition def;
  item.expect_section("pneumatic_compensator");
  def.stroke = read_stroke(item["stroke"]);
  PneumaticParameters& p = def.parameters;
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
  return def;
}

void PneumaticCompensatorDefinition::build(const std::string& name, SceneBuildContext& context) const {
  const Model& model = context.model;
  Data& data = context.initial_state().data;
  try {
    const StrokeAxis axis = resolve_stroke(context, name, stroke);
    const VectorX unit = unit_stroke_generalized_force(axis, model, data);
    const double initial_stroke = stroke_motion(axis, model, data).stroke;
    const EndStops& stops = parameters.end_stops;
    if (initial_stroke < stops.lower || initial_stroke > stops.upper)
      throw context.error(name, "end_stops",
                          fmt::format("an initial stroke of {:g} m, outside the end stops [{:g}, {:g}] m",
                                      initial_stroke, stops.lower, stops.upper),
                          "an initial state between the end stops");
    PneumaticParameters built = parameters;
    if (balance_pressure)
      built = balanced_pneumatic(
          parameters, static_stroke_load(model, data, context.system, context.t_start, context.initial_configuration(), unit),
          initial_stroke);
    context.summarised.pneumatic_compensators.push_back(
        add_element(context.system, std::make_unique<PneumaticCompensator>(name, axis, built)));
    context.compensators_on_strokes.push_back({&stroke, [built](const Model&, const StrokeAxis& analysis_axis) {
                                                 return std::make_unique<PneumaticCompensator>("pneumatic",
                                                                                               analysis_axis, built);
                                               }});
  } catch (const ParameterError& error) {
    throw to_input_error(context.definition, context.definition.item_paths.at(name), error, compensator_keys());
  }
}

}  // namespace heavesim
