#pragma once
// The passive pneumatic compensator (docs/physics/compensators.md §2-6):
// cylinders of total piston area A whose oil side is connected through piping to an
// accumulator backed by air pressure vessels holding gas volume V(s) = V0 + A s. When
// the rods extend (s grows) oil leaves the accumulator and the gas expands.
//
//   F = (p_gas - dp_pipe(A ds/dt) - p_atm) A + F_friction(ds/dt) + F_end_stops(s, ds/dt)
//
// Gas law, by what the case asks for (nothing evaluated that is not needed):
//  * one polytropic exponent n, no heat exchange: p = p0 (V0/V)^n -- algebraic, no state;
//  * otherwise one state, the gas temperature T (stored as T / T0), from the first
//    law for an ideal gas of fixed mass with the process exponent n and Newton cooling
//    to the vessel walls:
//        dT/dt = -(n_eff - 1) T dV/dt / V + (T_wall - T) / tau,    p = p0 (T/T0) (V0/V),
//    n_eff = (n_c + n_e)/2 + (n_e - n_c)/2 tanh(ds/dt / v_h).
//    With n = gamma (1.4) and cooling this is the standard heat-transfer gas spring:
//    adiabatic for fast strokes, isothermal for slow ones, with a hysteresis loop in
//    between. Separate exponents for compression (n_c) and expansion (n_e) are MBARI's
//    direction-dependent polytrope; the tanh switch (width v_h) keeps the right-hand
//    side smooth. Note: with n_c != n_e the loop does not close by itself -- the net
//    work of each cycle stays in the gas as heat -- so give a cooling time constant, or
//    the mean pressure creeps (docs/case-format.md).
#include <optional>

#include "control/pneumatic/piping_loss.hpp"
#include "control/stroke/end_stops.hpp"
#include "control/stroke/seal_friction.hpp"
#include "control/stroke/stroke_element.hpp"

namespace heavesim {

/// Newton cooling of the gas to the vessel walls: dT/dt += (T_wall - T) / tau.
struct GasCooling {
  double time_constant = 60.0;       // tau [s], > 0
  double wall_temperature = 288.15;  // T_wall [K], > 0
};

struct PneumaticParameters {
  double piston_area = 0.1735;          // A [m^2], all cylinders together
  double gas_volume = 60.0;             // V0 [m^3] at mid-stroke (s = 0)
  double gas_pressure = 15e6;           // p0 [Pa], absolute, at s = 0 and T0
  double atmospheric_pressure = 101325.0;  // p_atm [Pa], on the rod side
  double exponent_compression = 1.4;    // n_c [-]
  double exponent_expansion = 1.4;      // n_e [-]
  double hysteresis_speed = 0.01;       // v_h [m/s], width of the n_c/n_e switch
  double initial_temperature = 288.15;  // T0 [K]
  std::optional<GasCooling> cooling;    // none: no heat exchange
  PipingLoss piping;
  SealFriction friction;
  EndStops end_stops;

  /// True when the gas needs its temperature state (cooling or n_c != n_e).
  bool has_gas_state() const { return cooling.has_value() || exponent_compression != exponent_expansion; }
};

/// Everything the compensator's force depends on, at one state.
struct PneumaticState {
  double stroke, stroke_rate;  // m, m/s
  double gas_volume;           // m^3
  double gas_pressure;         // Pa, absolute
  double gas_temperature;      // K
  double oil_flow;             // m^3/s into the cylinders (A ds/dt)
  double cylinder_pressure;    // Pa, absolute: gas pressure minus the piping loss
  double gas_force;            // N: (p_cyl - p_atm) A
  double friction_force;       // N
  double end_stop_force;       // N
  double force;                // N: the total, positive extends the stroke
  double stiffness;            // N/m: n_eff p A^2 / V (the gas alone, no heat exchange)
  double power;                // W: force * ds/dt, delivered to the moving side
  double piping_loss_power;    // W: dp_pipe * Q >= 0
};

class PneumaticCompensator : public StrokeElement<PneumaticState, PneumaticParameters> {
 public:
  PneumaticCompensator(std::string name, StrokeAxis axis, PneumaticParameters parameters);

  int state_size() const override { return parameters_.has_gas_state() ? 1 : 0; }
  void initial_state(Eigen::Ref<VectorX> z) const override;
  /// Throws NumericalError if the gas volume is gone (the stroke ran far past a stop).
  PneumaticState evaluate(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
                          double* zdot) const override;
  /// Energy [J] stored relative to mid-stroke at T0 (s = 0, V = V0, p = p0): the gas's
  /// (p V - p0 V0) / (n - 1) (its internal energy for n = gamma; -p0 V0 ln(V / V0) for
  /// n = 1), the atmosphere's p_atm (V - V0) on the rod side, and the end stops' springs.
  /// -dE/ds is then the conservative part of the force, (p - p_atm) A + stops. With the
  /// temperature state, p V = p0 V0 T/T0 and n is the mean of n_c and n_e.
  double potential_energy(const Model& model, const Data& data, Eigen::Ref<const VectorX> z) const override;
};

/// The exponent between n_c (compressing, ds/dt < 0) and n_e (expanding) at stroke rate v.
double effective_exponent(const PneumaticParameters& parameters, double stroke_rate);

}  // namespace heavesim
