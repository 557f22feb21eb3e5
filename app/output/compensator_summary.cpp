#include "app/output/compensator_summary.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

namespace heavesim {

CompensatorSummary::CompensatorSummary(const MultibodySystem& system, const SummarisedElements& elements,
                                       double evaluate_after)
    : evaluate_after_(evaluate_after) {
  for (const auto& [pneumatic, index] : elements.pneumatic_compensators)
    passive_.push_back({pneumatic, index, system.state_offset(index), EndStopMonitor(pneumatic->parameters().end_stops)});
  for (const auto& [active, index] : elements.active_compensators)
    active_.push_back({active, index, system.state_offset(index)});
  for (const auto& [contact, index] : elements.ground_contacts) contacts_.push_back({contact, index});
  // measure() finds the elements by index, in any build of the case.
  const auto at = [&system](std::size_t index) { return system.force_elements().at(index).get(); };
  bool placed = true;
  for (const Passive& p : passive_) placed = placed && at(p.index) == p.element;
  for (const Active& a : active_) placed = placed && at(a.index) == a.element;
  for (const Contact& c : contacts_) placed = placed && at(c.index) == c.element;
  if (!placed) throw std::logic_error("CompensatorSummary: an element is not at its index in the system");
  measured_values_ = static_cast<int>(5 * passive_.size() + contacts_.size() + 3 * active_.size());
}

void CompensatorSummary::measure(const MultibodySystem& system, double t, const VectorX& y, double* values) const {
  const Model& model = system.model();
  const Data& data = system.data();
  for (const Passive& p : passive_) {
    const PneumaticCompensator& element = element_of<PneumaticCompensator>(system, p.index);
    const PneumaticState& s = element.evaluated(t, model, data, y.segment(p.offset, element.state_size()));
    // The moving side sits (mid-stroke + s) along the stroke axis from the base.
    *values++ = s.stroke;
    *values++ = s.gas_pressure;
    *values++ = s.gas_temperature;
    // The heights only where observe() reads them: in the evaluation window.
    double base_height = std::numeric_limits<double>::quiet_NaN(), load_height = base_height;
    if (in_window(t)) {
      const StrokeAxis& axis = element.axis();
      const BaseMotion base = base_motion(axis, model, data);
      base_height = base.position_world.z();
      load_height = base_height + base.axis_world.z() * (axis.mid_stroke + s.stroke);
    }
    *values++ = base_height;
    *values++ = load_height;
  }
  for (const Contact& c : contacts_) *values++ = element_of<GroundContact>(system, c.index).state(data).force;
  for (const Active& a : active_) {
    const ActiveCompensator& element = element_of<ActiveCompensator>(system, a.index);
    const ActiveState& s = element.evaluated(t, model, data, y.segment(a.offset, element.state_size()));
    *values++ = s.force;
    *values++ = s.error;
    *values++ = s.supply_power;
  }
}

void CompensatorSummary::observe(double t, const double* values) {
  for (Passive& p : passive_) {
    const double stroke = values[0], pressure = values[1], temperature = values[2];
    p.monitor.observe(stroke);
    p.max_stroke = std::max(p.max_stroke, stroke);
    p.min_stroke = std::min(p.min_stroke, stroke);
    p.max_pressure = std::max(p.max_pressure, pressure);
    p.min_pressure = std::min(p.min_pressure, pressure);
    p.max_temperature = std::max(p.max_temperature, temperature);
    p.min_temperature = std::min(p.min_temperature, temperature);
    if (in_window(t)) {
      p.base_height.add(values + 3);
      p.load_height.add(values + 4);
    }
    values += 5;
  }
  for (Contact& c : contacts_) {
    const double force = *values++;
    if (!in_window(t)) continue;
    c.force.add(&force);
    c.lifted_samples += force <= 0.0;
  }
  for (Active& a : active_) {
    const double force = values[0], error = values[1], supply_power = values[2];
    values += 3;
    a.max_force = std::max(a.max_force, std::abs(force));
    a.max_error = std::max(a.max_error, std::abs(error));
    a.max_supply_power = std::max(a.max_supply_power, supply_power);
    if (a.samples == 0) a.first_time = t;
    if (a.samples > 0) a.supply_energy += 0.5 * (supply_power + a.last_supply_power) * (t - a.last_time);  // trapezoid
    a.last_supply_power = supply_power;
    a.last_time = t;
    ++a.samples;
  }
}

double CompensatorSummary::efficiency(std::size_t k) const {
  const Passive& p = passive_[k];
  const double base = p.base_height.standard_deviation()[0];
  if (p.base_height.count() < 2 || base <= 1e-12) return std::numeric_limits<double>::quiet_NaN();
  return 1.0 - p.load_height.standard_deviation()[0] / base;
}

void CompensatorSummary::write(ResultFile& file) const {
  for (std::size_t k = 0; k < passive_.size(); ++k) {
    const Passive& p = passive_[k];
    const std::string prefix = p.element->name() + "_";
    if (std::isfinite(efficiency(k))) file.set_attribute("/summary", prefix + "efficiency", efficiency(k));
    file.set_attribute("/summary", prefix + "efficiency_window_start_s", evaluate_after_);
    file.set_attribute("/summary", prefix + "base_heave_std_m", p.base_height.standard_deviation()[0]);
    file.set_attribute("/summary", prefix + "load_heave_std_m", p.load_height.standard_deviation()[0]);
    file.set_attribute("/summary", prefix + "stroke_min_m", p.min_stroke);
    file.set_attribute("/summary", prefix + "stroke_max_m", p.max_stroke);
    file.set_attribute("/summary", prefix + "end_stop_events_lower", p.monitor.lower_events());
    file.set_attribute("/summary", prefix + "end_stop_events_upper", p.monitor.upper_events());
    file.set_attribute("/summary", prefix + "end_stop_max_penetration_m", p.monitor.max_penetration());
    file.set_attribute("/summary", prefix + "gas_pressure_min_Pa", p.min_pressure);
    file.set_attribute("/summary", prefix + "gas_pressure_max_Pa", p.max_pressure);
    file.set_attribute("/summary", prefix + "gas_temperature_min_K", p.min_temperature);
    file.set_attribute("/summary", prefix + "gas_temperature_max_K", p.max_temperature);
  }
  for (const Active& a : active_) {
    const std::string prefix = a.element->name() + "_";
    file.set_attribute("/summary", prefix + "force_max_abs_N", a.max_force);
    file.set_attribute("/summary", prefix + "control_error_max_abs_m", a.max_error);
    if (a.element->parameters().actuator == ActuatorType::hydraulic) {
      file.set_attribute("/summary", prefix + "supply_power_max_W", a.max_supply_power);
      file.set_attribute("/summary", prefix + "supply_energy_J", a.supply_energy);
    }
  }
  for (const Contact& c : contacts_) {
    if (c.force.count() == 0) continue;
    const std::string prefix = c.element->name() + "_";
    file.set_attribute("/summary", prefix + "force_mean_N", c.force.mean()[0]);
    file.set_attribute("/summary", prefix + "force_std_N", c.force.standard_deviation()[0]);
    file.set_attribute("/summary", prefix + "force_min_N", c.force.minimum()[0]);
    file.set_attribute("/summary", prefix + "force_max_N", c.force.maximum()[0]);
    file.set_attribute("/summary", prefix + "lifted_samples", c.lifted_samples);
  }
}

std::vector<std::string> CompensatorSummary::headlines() const {
  std::vector<std::string> lines;
  for (std::size_t k = 0; k < passive_.size(); ++k) {
    const Passive& p = passive_[k];
    const EndStops& stops = p.element->parameters().end_stops;
    if (std::isfinite(efficiency(k)))
      lines.push_back(fmt::format("compensator '{}': efficiency {:.4f} (1 - std of the load's heave {:.4g} m / std of "
                                  "the derrick top's {:.4g} m, from t = {:g} s)",
                                  p.element->name(), efficiency(k), p.load_height.standard_deviation()[0], p.base_height.standard_deviation()[0],
                                  evaluate_after_));
    lines.push_back(fmt::format(
        "compensator '{}': stroke {:.4g} .. {:.4g} m (stops {:g} .. {:g}), end-stop contacts {} lower / {} upper, "
        "gas pressure {:.5g} .. {:.5g} MPa, temperature {:.4g} .. {:.4g} K",
        p.element->name(), p.min_stroke, p.max_stroke, stops.lower, stops.upper, p.monitor.lower_events(),
        p.monitor.upper_events(), p.min_pressure * 1e-6, p.max_pressure * 1e-6, p.min_temperature, p.max_temperature));
  }
  for (const Active& a : active_) {
    std::string line = fmt::format("compensator '{}': peak force {:.4g} kN, peak control error {:.4g} m",
                                   a.element->name(), a.max_force * 1e-3, a.max_error);
    if (a.element->parameters().actuator == ActuatorType::hydraulic && a.last_time > a.first_time)
      line += fmt::format(", hydraulic power peak {:.4g} kW, mean {:.4g} kW", a.max_supply_power * 1e-3,
                          a.supply_energy / (a.last_time - a.first_time) * 1e-3);
    lines.push_back(line);
  }
  for (const Contact& c : contacts_)
    if (c.force.count() > 0)
      lines.push_back(fmt::format("contact '{}': force mean {:.4g} kN, std {:.4g} kN, range {:.4g} .. {:.4g} kN "
                                  "(from t = {:g} s), {} of {} samples lifted off",
                                  c.element->name(), c.force.mean()[0] * 1e-3, c.force.standard_deviation()[0] * 1e-3,
                                  c.force.minimum()[0] * 1e-3, c.force.maximum()[0] * 1e-3, evaluate_after_,
                                  c.lifted_samples, c.force.count()));
  return lines;
}

}  // namespace heavesim
