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

}  // namespace heavesim
