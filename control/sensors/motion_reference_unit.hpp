#pragma once
// A motion reference unit's heave output (docs/physics/compensators.md §10): an MRU integrates
// its accelerometers twice through a high-pass filter, so its heave is, in effect, the
// true heave z through
//   H(s) = s^2 / (s^2 + 2 zeta w_c s + w_c^2)  (second-order high-pass, corner w_c = 2 pi / T_c)
// followed by the output lag 1 / (1 + tau s). The filter has a phase lead at long
// periods (the residual heave error of a compensator in swell); the lag models the
// processing and transmission delay.
//
// States, all in metres: u1, u2 of the high-pass filter in scaled companion form and
// the lag output w,
//   du1/dt = w_c u2,  du2/dt = w_c y,  y = z - u1 - 2 zeta u2   (high-pass output)
//   dw/dt  = (y - w) / tau
// The measured heave is w; its rate dw/dt and acceleration
//   d2w/dt2 = (dy/dt - dw/dt) / tau,   dy/dt = dz/dt - w_c u2 - 2 zeta w_c y,
// need only z and dz/dt, not the (not yet known) true acceleration: they are the
// MRU's velocity and acceleration outputs for feed-forward.
namespace heavesim {

struct MruParameters {
  double corner_period = 100.0;  // T_c [s] of the high-pass filter (w_c = 2 pi / T_c)
  double damping = 0.7071067811865476;  // zeta [-] (Butterworth)
  double lag = 0.01;             // tau [s], > 0
};

struct MruOutput {
  double heave;          // m
  double heave_rate;     // m/s
  double heave_acceleration;  // m/s^2
  double rates[3];       // du1/dt, du2/dt, dw/dt
};

/// States (u1, u2, w) [m], true heave z [m] (from its initial value) and its rate [m/s].
inline MruOutput mru_output(const MruParameters& mru, const double* states, double heave, double heave_rate) {
  const double w_c = 2.0 * 3.141592653589793 / mru.corner_period;
  const double u1 = states[0], u2 = states[1], w = states[2];
  const double y = heave - u1 - 2.0 * mru.damping * u2;
  const double y_rate = heave_rate - w_c * u2 - 2.0 * mru.damping * w_c * y;
  MruOutput out;
  out.heave = w;
  out.heave_rate = (y - w) / mru.lag;
  out.heave_acceleration = (y_rate - out.heave_rate) / mru.lag;
  out.rates[0] = w_c * u2;
  out.rates[1] = w_c * y;
  out.rates[2] = out.heave_rate;
  return out;
}

}  // namespace heavesim
