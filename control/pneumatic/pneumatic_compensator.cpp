#include "control/pneumatic/pneumatic_compensator.hpp"

#include <cmath>

#include "control/pneumatic/gas_spring.hpp"
#include "kernel/math/numerical_error.hpp"

namespace heavesim {

double effective_exponent(const PneumaticParameters& parameters, double stroke_rate) {
  const double mean = 0.5 * (parameters.exponent_compression + parameters.exponent_expansion);
  const double half_difference = 0.5 * (parameters.exponent_expansion - parameters.exponent_compression);
  if (half_difference == 0.0) return mean;
  return mean + half_difference * std::tanh(stroke_rate / parameters.hysteresis_speed);
}

PneumaticCompensator::PneumaticCompensator(std::string name, StrokeAxis axis, PneumaticParameters parameters)
    : StrokeElement(std::move(name), axis, parameters) {
  using S = PneumaticState;
  table_.add("stroke", "m", "stroke from mid-stroke along the axis, positive when the rods extend", &S::stroke);
  table_.add("stroke_rate", "m/s", "rate of the stroke", &S::stroke_rate);
  table_.add("gas_volume", "m^3", "gas volume V0 + A s in accumulator and air pressure vessels", &S::gas_volume);
  table_.add("gas_pressure", "Pa", "absolute gas pressure", &S::gas_pressure);
  table_.add("gas_temperature", "K", "gas temperature", &S::gas_temperature);
  table_.add("oil_flow", "m^3/s", "oil flow from the accumulator into the cylinders, A ds/dt", &S::oil_flow);
  table_.add("cylinder_pressure", "Pa", "absolute oil pressure at the pistons: gas pressure minus the piping loss",
             &S::cylinder_pressure);
  table_.add("gas_force", "N", "pressure force (p_cyl - p_atm) A on the moving side, positive extends", &S::gas_force);
  table_.add("friction_force", "N", "seal friction on the moving side, positive extends", &S::friction_force);
  table_.add("end_stop_force", "N", "end-stop force on the moving side, positive extends", &S::end_stop_force);
  table_.add("force", "N", "total compensator force on the moving side along the stroke axis, positive extends",
             &S::force);
  table_.add("stiffness", "N/m", "local gas-spring stiffness n p A^2 / V", &S::stiffness);
  table_.add("power", "W", "power delivered to the moving side, force * ds/dt", &S::power);
  table_.add("piping_loss_power", "W", "power dissipated in the piping, dp * Q >= 0", &S::piping_loss_power);
}

void PneumaticCompensator::initial_state(Eigen::Ref<VectorX> z) const {
  if (z.size() > 0) z[0] = 1.0;  // T / T0
}

PneumaticState PneumaticCompensator::evaluate(double t, const Model& model, const Data& data,
                                              Eigen::Ref<const VectorX> z, double* zdot) const {
  const PneumaticParameters& p = parameters_;
  const StrokeMotion motion = stroke_motion(axis_, model, data);
  PneumaticState s;
  s.stroke = motion.stroke;
  s.stroke_rate = motion.rate;
  s.gas_volume = p.gas_volume + p.piston_area * motion.stroke;
  if (!(s.gas_volume > 0.0))
    throw NumericalError(t,
                         "pneumatic compensator '" + name_ + "': the gas volume is gone (V = " +
                             std::to_string(s.gas_volume) + " m^3 at stroke " + std::to_string(motion.stroke) + " m)",
                         "the stroke ran far past the end stops: a load or a prescribed motion (a driver on the "
                         "stroke's joint) they cannot hold, or end stops too soft; check the end-stop stiffness, "
                         "the load, the gas pressure and any driver");
  const double n = effective_exponent(p, motion.rate);
  if (z.size() > 0) {
    // Ideal gas of fixed mass: p V / T constant; theta = T / T0 is the state.
    const double theta = z[0];
    s.gas_temperature = p.initial_temperature * theta;
    s.gas_pressure = p.gas_pressure * theta * p.gas_volume / s.gas_volume;
    if (zdot) {
      // First law: d theta/dt = -(n_eff - 1) theta (dV/dt) / V + (theta_wall - theta) / tau.
      zdot[0] = -(n - 1.0) * theta * p.piston_area * motion.rate / s.gas_volume;
      if (p.cooling) zdot[0] += (p.cooling->wall_temperature / p.initial_temperature - theta) / p.cooling->time_constant;
    }
  } else {
    s.gas_pressure = polytropic_pressure(p.gas_pressure, p.gas_volume, s.gas_volume, n);
    s.gas_temperature = polytropic_temperature(p.initial_temperature, p.gas_volume, s.gas_volume, n);
  }
  s.oil_flow = p.piston_area * motion.rate;
  s.cylinder_pressure = s.gas_pressure - piping_pressure_drop(p.piping, s.oil_flow);
  s.gas_force = (s.cylinder_pressure - p.atmospheric_pressure) * p.piston_area;
  s.friction_force = seal_friction_force(p.friction, motion.rate);
  s.end_stop_force = end_stop_force(p.end_stops, motion.stroke, motion.rate);
  s.force = s.gas_force + s.friction_force + s.end_stop_force;
  s.stiffness = polytropic_stiffness(s.gas_pressure, s.gas_volume, p.piston_area, n);
  s.power = s.force * motion.rate;
  s.piping_loss_power = (s.gas_pressure - s.cylinder_pressure) * s.oil_flow;
  return s;
}

double PneumaticCompensator::potential_energy(const Model& model, const Data& data, Eigen::Ref<const VectorX> z) const {
  const PneumaticParameters& p = parameters_;
  const double stroke = stroke_motion(axis_, model, data).stroke;
  const double V = p.gas_volume + p.piston_area * stroke;
  const double p0V0 = p.gas_pressure * p.gas_volume;
  const double n = 0.5 * (p.exponent_compression + p.exponent_expansion);
  double gas;
  if (std::abs(n - 1.0) < 1e-12)
    gas = -p0V0 * std::log(V / p.gas_volume);  // isothermal: the work the gas can still do
  else if (z.size() > 0)
    gas = p0V0 * (z[0] - 1.0) / (n - 1.0);  // p V = p0 V0 T/T0
  else
    gas = (polytropic_pressure(p.gas_pressure, p.gas_volume, V, n) * V - p0V0) / (n - 1.0);
  return gas + p.atmospheric_pressure * (V - p.gas_volume) + end_stop_energy(p.end_stops, stroke);
}

}  // namespace heavesim
