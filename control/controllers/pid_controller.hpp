#pragma once
// PID with derivative on the measurement and back-calculation anti-windup
// (Astrom & Hagglund, "Advanced PID Control", 2006, §3.5 and §6.5):
//   u     = K_p e + K_i I - K_d dy/dt + u_ff,       e = r - y
//   u_sat = clamp(u, -u_max, u_max)
//   dI/dt = e + (u_sat - u) / (K_i T_t)
// The derivative acts on the measurement y, not on e, so a step of the reference
// gives no derivative kick. While the output saturates, the second term bleeds the
// integral back with time constant T_t, so it does not wind up; unlike switching the
// integration off it keeps the right-hand side continuous, which error-controlled
// integrators need. Default T_t = sqrt(T_i T_d) = sqrt(K_d / K_i) (Astrom's rule),
// or T_i = K_p / K_i without derivative action.
#include <algorithm>
#include <cmath>

namespace heavesim {

struct PidGains {
  double proportional = 0.0;      // K_p [command/m]
  double integral = 0.0;          // K_i [command/(m s)]
  double derivative = 0.0;        // K_d [command s/m]
  double tracking_time = 0.0;     // T_t [s]; 0 = the default above
  double output_limit = 1.0;      // u_max [command], > 0
};

/// The anti-windup tracking time constant T_t [s] actually used.
inline double tracking_time(const PidGains& gains) {
  if (gains.tracking_time > 0.0) return gains.tracking_time;
  if (gains.integral <= 0.0) return 0.0;
  return gains.derivative > 0.0 ? std::sqrt(gains.derivative / gains.integral) : gains.proportional / gains.integral;
}

struct PidOutput {
  double command;            // u, before saturation
  double saturated_command;  // u_sat
  double integral_rate;      // dI/dt [m]
};

/// e [m], dy/dt [m/s], the integral state I [m s] and the feed-forward u_ff [command].
inline PidOutput pid_output(const PidGains& gains, double error, double measurement_rate, double integral,
                            double feedforward) {
  PidOutput out;
  out.command = gains.proportional * error + gains.integral * integral - gains.derivative * measurement_rate + feedforward;
  out.saturated_command = std::clamp(out.command, -gains.output_limit, gains.output_limit);
  out.integral_rate = error;
  if (gains.integral > 0.0)
    out.integral_rate += (out.saturated_command - out.command) / (gains.integral * tracking_time(gains));
  return out;
}

}  // namespace heavesim
