#pragma once
// Closed-loop poles of a compensator configuration, for checking controller gains
// before a run. The compensator elements are rebuilt on a one-degree-of-freedom
// model -- a body of the apparent mass along the stroke on a vertical prismatic joint
// from the ground (the platform held still), no gravity, a constant force holding it
// at the initial state -- and the whole system dy/dt = f(y) is linearized there by
// central differences. Its eigenvalues are the poles of the stroke loop: passive gas
// spring, controller, sensor and actuator dynamics together, as the elements
// implement them (no separate linear model that could disagree with them).
#include <complex>
#include <functional>
#include <memory>
#include <vector>

#include <string>

#include "control/active/active_compensator.hpp"
#include "control/stroke/stroke_axis.hpp"

namespace heavesim {

/// Builds one compensator element on the analysis model: the stroke is that model's
/// prismatic joint, the base the ground, the moving side (and controlled point) the body.
using StrokeElementFactory = std::function<std::unique_ptr<ForceElement>(const Model& model, const StrokeAxis& axis)>;

struct StrokeLoopPoles {
  std::vector<std::complex<double>> poles;  // 1/s
  double largest_real_part = 0.0;           // 1/s
};

/// The poles for a moving mass [kg] and the elements that act on the stroke.
StrokeLoopPoles stroke_loop_poles(double mass, const std::vector<StrokeElementFactory>& elements);

/// Throws ParameterError("controller") when a pole of the active compensator's stroke
/// loop (carried mass `apparent_mass` [kg]) has a real part above max(1e-6 |largest
/// pole|, 2e-3 1/s), naming the pole and how to choose stable gains.
void check_stroke_loop_stable(const StrokeLoopPoles& poles, const ActiveCompensatorParameters& active,
                              double apparent_mass);

/// How to choose stable gains for the compensator's actuator: pole placement on the
/// carried mass for a force actuator; for a valve-driven cylinder a position-loop gain
/// well below 2 zeta_h omega_h, omega_h = sqrt(beta (A_A^2 / V_A + A_B^2 / V_B) / m)
/// (Merritt, Hydraulic Control Systems, 1967) with the carried mass m = `apparent_mass` [kg].
std::string stable_gain_advice(const ActiveCompensatorParameters& active, double apparent_mass);

}  // namespace heavesim
