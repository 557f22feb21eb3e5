#pragma once
// The active heave compensator (docs/physics/compensators.md §7-11): a
// sensor, a controller and an actuator acting along a stroke axis, in parallel with
// the passive compensator.
//
// Measurement. The controlled variable is the earth-fixed heave z_c of a point (the
// crown block, or the hook) relative to its initial value. Either the true state
// (the point's world z), or as a rig measures it: the heave of the stroke base (the
// derrick) from a motion reference unit plus the stroke, z_c = w_MRU + (s - s(0))
// (exact for a vertical stroke axis). The platform heave rate and acceleration at the
// base feed forward: the true rate, or the MRU's outputs (acceleration feed-forward
// needs the MRU: the true acceleration is not known before the dynamics are solved).
//
// Controller. PID on e = r - z_c with derivative on the measurement and back-calculation
// anti-windup (pid_controller.hpp), feed-forward u_ff = -K_v v_p - K_a a_p (minus: the
// stroke must cancel the platform's motion), and optional stroke centring: the reference
// drifts so that the stroke returns to s_c, dr/dt = -(s - s_c) / T_c.
//
// Actuator. Either a force actuator (first-order lag, saturation, rate limit;
// the command is a force [N]) or a servo valve driving a double-acting cylinder with
// compressible oil. A valve-driven cylinder is a velocity source, so there the command
// is a stroke-speed demand v_d [m/s] (gains in 1/s, 1/s^2, -; feed-forward K_v = 1
// cancels the platform's heave rate), limited to max_speed, and turned into a spool
// command by inverting the orifice law at the measured chamber pressure (flow
// linearization, as AHC controllers with pressure transmitters do):
//   x = A_A v_d / (K sqrt(p_S - p_A)) extending,  A_A v_d / (K sqrt(p_A - p_T)) retracting,
// clamped to -1 ... 1 (drops below the laminar transition dp_t count as dp_t). The
// chamber pressures are stiff states (time scales 1/omega_h and the spool's 1/omega_v):
// integrate with IDA, whose steps follow the accuracy asked for, not these time scales
// (docs/performance.md).
//
// States (only those the configuration needs, in this order): the PID integral I [m s],
// the reference offset r [m] (centring), the MRU states u1, u2, w [m], then the
// actuator: F / F_max (force actuator with a lag), or x_v, (dx_v/dt) / omega_v,
// p_A / p_S, p_B / p_S (hydraulic; scaled so that all are of order one).
#include <optional>

#include "control/controllers/pid_controller.hpp"
#include "control/hydraulic/force_actuator.hpp"
#include "control/hydraulic/hydraulic_cylinder.hpp"
#include "control/hydraulic/servo_valve.hpp"
#include "control/sensors/motion_reference_unit.hpp"
#include "control/stroke/stroke_element.hpp"

namespace heavesim {

enum class ActuatorType { force, hydraulic };

struct HydraulicActuatorParameters {
  HydraulicCylinderParameters cylinder;
  ServoValveParameters valve;
  HydraulicSupply supply;
  /// Largest stroke speed the controller asks for [m/s]; default (NaN): the speed the
  /// fully open valve gives with half the supply pressure across the land,
  /// K sqrt((p_S - p_T) / 2) / A_A.
  double max_speed = std::numeric_limits<double>::quiet_NaN();
  /// Initial chamber pressures [Pa]; default (NaN): zero force with p_A + p_B = p_S.
  double initial_pressure_a = std::numeric_limits<double>::quiet_NaN();
  double initial_pressure_b = std::numeric_limits<double>::quiet_NaN();
};

struct ActiveCompensatorParameters {
  ActuatorType actuator = ActuatorType::force;
  ForceActuatorParameters force_actuator;
  HydraulicActuatorParameters hydraulic;
  PidGains gains;  // output_limit is set from the actuator (F_max, or the hydraulic max_speed)
  double velocity_feedforward = 0.0;      // K_v [command s/m]
  double acceleration_feedforward = 0.0;  // K_a [command s^2/m], needs the MRU
  double centring_time = 0.0;             // T_c [s], 0 = no centring
  double centre_stroke = 0.0;             // s_c [m]
  BodyPoint controlled_point;             // true-state measurement of z_c
  std::optional<MruParameters> mru;       // measure as a rig does (MRU + stroke)
  // The initial state, taken by whoever builds the element:
  double controlled_height = 0.0;  // z_c at t = 0 [m, world]
  double base_height = 0.0;        // z of the stroke base at t = 0 [m, world]
  double initial_stroke = 0.0;     // s at t = 0 [m]
};

/// Everything the element computes at one state (the output channels read it).
struct ActiveState {
  double stroke, stroke_rate;                 // m, m/s
  double controlled_position, controlled_rate;  // measured z_c - z_c(0) [m], its rate [m/s]
  double reference, error;                    // r, e = r - z_c [m]
  double platform_heave, platform_heave_rate, platform_heave_acceleration;  // at the stroke base, measured
  double feedforward, command, saturated_command, integral;  // command units (N or m/s), I [m s]
  double actuator_force;                      // N, before cylinder friction
  double force;                               // N, total on the moving side, positive extends
  double power;                               // W, force * ds/dt
  // hydraulic actuator only
  double valve_command, spool_position, pressure_a, pressure_b, flow_a, flow_b, supply_flow, supply_power;
};

class ActiveCompensator : public StrokeElement<ActiveState, ActiveCompensatorParameters> {
 public:
  /// Throws ParameterError for a configuration it cannot run (acceleration
  /// feed-forward without an MRU, a rate limit without a lag).
  ActiveCompensator(std::string name, StrokeAxis axis, ActiveCompensatorParameters parameters);

  int state_size() const override { return size_; }
  void initial_state(Eigen::Ref<VectorX> z) const override;
  ActiveState evaluate(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
                       double* zdot) const override;

 private:
  // state offsets, -1 when absent
  int integral_ = -1, reference_ = -1, mru_ = -1, actuator_ = -1;
  int size_ = 0;
};

}  // namespace heavesim
