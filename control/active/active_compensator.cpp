#include "control/active/active_compensator.hpp"

#include <algorithm>
#include <cmath>

#include "kernel/parameter_error.hpp"

namespace heavesim {

ActiveCompensator::ActiveCompensator(std::string name, StrokeAxis axis, ActiveCompensatorParameters parameters)
    : StrokeElement(std::move(name), axis, parameters) {
  ActiveCompensatorParameters& p = parameters_;
  const bool hydraulic = p.actuator == ActuatorType::hydraulic;
  if (hydraulic && std::isnan(p.hydraulic.max_speed))
    p.hydraulic.max_speed = p.hydraulic.valve.flow_coefficient() *
                            std::sqrt(0.5 * (p.hydraulic.supply.supply_pressure - p.hydraulic.supply.tank_pressure)) /
                            p.hydraulic.cylinder.area_a;
  p.gains.output_limit = hydraulic ? p.hydraulic.max_speed : p.force_actuator.max_force;
  // The true acceleration is not known before the dynamics are solved; the MRU's is.
  if (p.acceleration_feedforward != 0.0 && !p.mru)
    throw ParameterError(
        "acceleration_feedforward", "acceleration feed-forward without an MRU",
        "measurement.mru (the true acceleration is not known before the dynamics are solved; the MRU's is)");
  // The rate limit bounds dF/dt of the first-order lag, which a lag of 0 does not have.
  if (!hydraulic && p.force_actuator.time_constant == 0.0 && std::isfinite(p.force_actuator.max_rate))
    throw ParameterError("max_rate", "a rate limit with time_constant = 0",
                         "time_constant > 0 (the rate limit acts on the lag)");
  if (hydraulic && std::isnan(p.hydraulic.initial_pressure_a)) {
    // Zero force: p_A A_A - p_B A_B = p_atm (A_A - A_B) with p_A + p_B = p_S.
    const HydraulicCylinderParameters& c = p.hydraulic.cylinder;
    const double p_s = p.hydraulic.supply.supply_pressure;
    p.hydraulic.initial_pressure_a = (p_s * c.area_b + c.atmospheric_pressure * (c.area_a - c.area_b)) / (c.area_a + c.area_b);
    p.hydraulic.initial_pressure_b = p_s - p.hydraulic.initial_pressure_a;
  }

  auto take = [this](int n) {
    const int offset = size_;
    size_ += n;
    return offset;
  };
  if (p.gains.integral > 0.0) integral_ = take(1);
  if (p.centring_time > 0.0) reference_ = take(1);
  if (p.mru) mru_ = take(3);
  if (hydraulic)
    actuator_ = take(4);
  else if (p.force_actuator.time_constant > 0.0)
    actuator_ = take(1);

  const std::string command_units = hydraulic ? "m/s" : "N";
  auto add = [this](std::string channel, std::string units, std::string description, double ActiveState::*field) {
    table_.add(std::move(channel), std::move(units), std::move(description), field);
  };
  add("stroke", "m", "stroke from mid-stroke along the axis, positive when the moving side extends", &ActiveState::stroke);
  add("stroke_rate", "m/s", "rate of the stroke", &ActiveState::stroke_rate);
  add("controlled_position", "m",
      p.mru ? "measured earth-fixed heave of the controlled point from its initial value: MRU heave + stroke change"
            : "earth-fixed heave (world z) of the controlled point from its initial value",
      &ActiveState::controlled_position);
  add("reference", "m", "reference for the controlled position (moves only with stroke centring)",
      &ActiveState::reference);
  add("error", "m", "control error: reference - controlled position", &ActiveState::error);
  add("platform_heave", "m",
      p.mru ? "heave of the stroke base (derrick) from its initial value, as the MRU reports it"
            : "heave (world z) of the stroke base (derrick) from its initial value",
      &ActiveState::platform_heave);
  add("platform_heave_rate", "m/s", p.mru ? "MRU heave rate at the stroke base" : "vertical velocity of the stroke base",
      &ActiveState::platform_heave_rate);
  if (p.mru)
    add("platform_heave_acceleration", "m/s^2", "MRU heave acceleration at the stroke base",
        &ActiveState::platform_heave_acceleration);
  if (integral_ >= 0) add("integral", "m s", "PID integral state", &ActiveState::integral);
  add("feedforward", command_units, "feed-forward command -K_v v_p - K_a a_p", &ActiveState::feedforward);
  add("command", command_units, "controller output before saturation", &ActiveState::command);
  add("saturated_command", command_units,
      hydraulic ? "stroke-speed demand after limiting to max_speed" : "force command after saturation",
      &ActiveState::saturated_command);
  if (hydraulic)
    add("valve_command", "-", "spool opening demanded from the stroke-speed demand by inverting the orifice law, -1 ... 1",
        &ActiveState::valve_command);
  add("actuator_force", "N",
      hydraulic ? "cylinder pressure force p_A A_A - p_B A_B - p_atm (A_A - A_B), positive extends"
                : "actuator force, positive extends",
      &ActiveState::actuator_force);
  add("force", "N", "total force on the moving side along the stroke axis (with cylinder friction), positive extends",
      &ActiveState::force);
  add("power", "W", "mechanical power delivered to the moving side, force * ds/dt", &ActiveState::power);
  if (hydraulic) {
    add("spool_position", "-", "servo-valve spool opening, -1 ... 1 (positive: supply to chamber A)",
        &ActiveState::spool_position);
    add("pressure_a", "Pa", "absolute pressure in chamber A (piston side, grows with the stroke)",
        &ActiveState::pressure_a);
    add("pressure_b", "Pa", "absolute pressure in chamber B (annulus side)", &ActiveState::pressure_b);
    add("flow_a", "m^3/s", "valve flow into chamber A", &ActiveState::flow_a);
    add("flow_b", "m^3/s", "valve flow into chamber B", &ActiveState::flow_b);
    add("supply_flow", "m^3/s", "flow drawn from the hydraulic power unit", &ActiveState::supply_flow);
    add("supply_power", "W", "hydraulic power drawn from the supply, (p_S - p_T) Q_S", &ActiveState::supply_power);
  }
}

void ActiveCompensator::initial_state(Eigen::Ref<VectorX> z) const {
  z.setZero();
  if (actuator_ >= 0 && parameters_.actuator == ActuatorType::hydraulic) {
    const HydraulicActuatorParameters& h = parameters_.hydraulic;
    z[actuator_ + 2] = h.initial_pressure_a / h.supply.supply_pressure;
    z[actuator_ + 3] = h.initial_pressure_b / h.supply.supply_pressure;
  }
}

ActiveState ActiveCompensator::evaluate(double, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
                                        double* zdot) const {
  const ActiveCompensatorParameters& p = parameters_;
  ActiveState s{};
  const StrokeMotion motion = stroke_motion(axis_, model, data);
  s.stroke = motion.stroke;
  s.stroke_rate = motion.rate;

  // Measurement.
  const BaseMotion base = base_motion(axis_, model, data);
  const double base_heave = base.position_world.z() - p.base_height;
  if (p.mru) {
    const MruOutput mru = mru_output(*p.mru, z.data() + mru_, base_heave, base.velocity_world.z());
    s.platform_heave = mru.heave;
    s.platform_heave_rate = mru.heave_rate;
    s.platform_heave_acceleration = mru.heave_acceleration;
    s.controlled_position = mru.heave + (motion.stroke - p.initial_stroke);
    s.controlled_rate = mru.heave_rate + motion.rate;
    if (zdot)
      for (int k = 0; k < 3; ++k) zdot[mru_ + k] = mru.rates[k];
  } else {
    s.platform_heave = base_heave;
    s.platform_heave_rate = base.velocity_world.z();
    s.platform_heave_acceleration = std::numeric_limits<double>::quiet_NaN();
    const Vector3 point = p.controlled_point.position_world(data);
    s.controlled_position = point.z() - p.controlled_height;
    s.controlled_rate = data.velocity_world[p.controlled_point.link].point_velocity(point).z();
  }

  // Controller.
  s.reference = reference_ >= 0 ? z[reference_] : 0.0;
  s.error = s.reference - s.controlled_position;
  s.integral = integral_ >= 0 ? z[integral_] : 0.0;
  s.feedforward = -p.velocity_feedforward * s.platform_heave_rate -
                  (p.mru ? p.acceleration_feedforward * s.platform_heave_acceleration : 0.0);
  const PidOutput pid = pid_output(p.gains, s.error, s.controlled_rate, s.integral, s.feedforward);
  s.command = pid.command;
  s.saturated_command = pid.saturated_command;
  if (zdot && integral_ >= 0) zdot[integral_] = pid.integral_rate;
  if (zdot && reference_ >= 0) zdot[reference_] = -(motion.stroke - p.centre_stroke) / p.centring_time;

  // Actuator.
  if (p.actuator == ActuatorType::force) {
    const ForceActuatorParameters& a = p.force_actuator;
    if (actuator_ >= 0) {
      s.actuator_force = a.max_force * z[actuator_];
      if (zdot) zdot[actuator_] = force_actuator_rate(a, s.actuator_force, s.saturated_command) / a.max_force;
    } else {
      s.actuator_force = s.saturated_command;
    }
    s.force = s.actuator_force;
  } else {
    const HydraulicActuatorParameters& h = p.hydraulic;
    const double p_s = h.supply.supply_pressure;
    const double omega = h.valve.natural_frequency;
    const double* x = z.data() + actuator_;  // x_v, (dx_v/dt)/omega_v, p_A/p_S, p_B/p_S
    s.spool_position = x[0];
    s.pressure_a = p_s * x[2];
    s.pressure_b = p_s * x[3];
    // Flow linearization: the opening that passes A_A v_d through the land now in use.
    const double land_drop = s.saturated_command >= 0.0 ? p_s - s.pressure_a : s.pressure_a - h.supply.tank_pressure;
    s.valve_command = std::clamp(h.cylinder.area_a * s.saturated_command /
                                     (h.valve.flow_coefficient() * std::sqrt(std::max(land_drop, h.valve.transition_pressure))),
                                 -1.0, 1.0);
    const ValveFlows flows = valve_flows(h.valve, h.supply, x[0], s.pressure_a, s.pressure_b);
    s.flow_a = flows.into_a;
    s.flow_b = flows.into_b;
    s.supply_flow = flows.supply;
    s.supply_power = (p_s - h.supply.tank_pressure) * flows.supply;
    s.actuator_force = cylinder_pressure_force(h.cylinder, s.pressure_a, s.pressure_b);
    s.force = s.actuator_force + seal_friction_force(h.cylinder.friction, motion.rate);
    if (zdot) {
      const ChamberVolumes volumes = chamber_volumes(h.cylinder, motion.stroke);
      const ChamberPressureRates rates =
          chamber_pressure_rates(h.cylinder, volumes, flows.into_a, flows.into_b, s.pressure_a, s.pressure_b,
                                 h.supply.tank_pressure, motion.rate);
      double* xdot = zdot + actuator_;
      // x'' = w^2 (u - x) - 2 zeta w x'  with y = x'/w:  x' = w y,  y' = w (u - x) - 2 zeta w y.
      xdot[0] = omega * x[1];
      xdot[1] = omega * (s.valve_command - x[0]) - 2.0 * h.valve.damping * omega * x[1];
      xdot[2] = rates.a / p_s;
      xdot[3] = rates.b / p_s;
    }
  }
  s.power = s.force * motion.rate;
  return s;
}

}  // namespace heavesim
