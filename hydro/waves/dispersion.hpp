#pragma once
// Linear (Airy) dispersion relation  w^2 = g k tanh(k h)  (e.g. Newman 1977, Marine
// Hydrodynamics, eq. 6.43), solved for the wave number k.
#include <limits>

namespace heavesim::hydro {

/// Water depth meaning "infinitely deep" (deep-water limit k = w^2 / g).
inline constexpr double infinite_depth = std::numeric_limits<double>::infinity();

/// The wave periods the linear gravity-wave models here serve [s]: below 0.1 s (waves
/// 1.6 cm long) surface tension governs, and the spectra's quadratures and frequency
/// bands assume periods of a sea; beyond 1000 s (tides, seiches) a wave is no sea state.
/// Angular frequencies 2 pi / period: 0.00628 .. 62.8 rad/s.
inline constexpr double shortest_wave_period = 0.1, longest_wave_period = 1000.0;

/// Throws ParameterError(field) unless shortest_wave_period <= period <= longest_wave_period;
/// `what` names the period in the message ("Tp", "T").
void check_wave_period(const char* field, const char* what, double period);

/// Wave number k [rad/m] of a linear wave of angular frequency w [rad/s] in water of
/// depth h [m] (infinite_depth allowed) under gravity g [m/s^2]; Newton iteration on
/// f(k) = g k tanh(k h) - w^2 to machine precision. w = 0 gives 0.
double wave_number(double angular_frequency, double depth, double gravity = 9.81);

/// Phase speed w / k [m/s] and group speed dw/dk [m/s] for the same arguments.
double phase_speed(double angular_frequency, double depth, double gravity = 9.81);
double group_speed(double angular_frequency, double depth, double gravity = 9.81);

}  // namespace heavesim::hydro
