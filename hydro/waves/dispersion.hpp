#pragma once
// Linear (Airy) dispersion relation  w^2 = g k tanh(k h)  (e.g. Newman 1977, Marine
// Hydrodynamics, eq. 6.43), solved for the wave number k.
#include <limits>

namespace heavesim::hydro {

/// Water depth meaning "infinitely deep" (deep-water limit k = w^2 / g).
inline constexpr double infinite_depth = std::numeric_limits<double>::infinity();

/// Wave number k [rad/m] of a linear wave of angular frequency w [rad/s] in water of
/// depth h [m] (infinite_depth allowed) under gravity g [m/s^2]; Newton iteration on
/// f(k) = g k tanh(k h) - w^2 to machine precision. w = 0 gives 0.
double wave_number(double angular_frequency, double depth, double gravity = 9.81);

/// Phase speed w / k [m/s] and group speed dw/dk [m/s] for the same arguments.
double phase_speed(double angular_frequency, double depth, double gravity = 9.81);
double group_speed(double angular_frequency, double depth, double gravity = 9.81);

}  // namespace heavesim::hydro
