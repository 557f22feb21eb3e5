#include "control/analysis/stroke_loop.hpp"

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include "kernel/elements/point_force.hpp"
#include "kernel/model/model_builder.hpp"
#include "kernel/parameter_error.hpp"
#include "kernel/system/multibody_system.hpp"

namespace heavesim {

StrokeLoopPoles stroke_loop_poles(double mass, const std::vector<StrokeElementFactory>& elements) {
  ModelBuilder builder;
  builder.set_gravity(Vector3::Zero());
  builder.add_body({"load", Inertia(mass, Vector3::Zero(), Matrix3::Identity() * mass), std::nullopt});
  JointDefinition stroke;
  stroke.name = "stroke";
  stroke.kind = JointKind::prismatic;
  stroke.axis = Vector3::UnitZ();
  stroke.parent = ModelBuilder::ground_name;
  stroke.child = "load";
  builder.add_joint(stroke);
  auto model = std::make_shared<const Model>(builder.build());
  const StrokeAxis axis = StrokeAxis::on_joint(*model, 1, 0.0);

  MultibodySystem system(model);
  for (const StrokeElementFactory& make : elements) system.add_force_element(make(*model, axis));
  VectorX y = system.initial_state(VectorX::Zero(1), VectorX::Zero(1));
  VectorX ydot(system.size());
  // Hold the initial state: a constant force cancels the elements' initial force (the
  // gas spring's preload, which in the rig carries the weight).
  system.state_derivative(0.0, y, ydot);
  const double preload = -mass * ydot[1];
  system.add_force_element(std::make_unique<PointForce>("preload", BodyPoint{1, Vector3::Zero()},
                                                        Vector3(0.0, 0.0, preload)));

  const int n = system.size();
  MatrixX jacobian(n, n);
  VectorX plus(n), minus(n);
  for (int k = 0; k < n; ++k) {
    const double h = 1e-6 * (1.0 + std::abs(y[k]));
    VectorX y_plus = y, y_minus = y;
    y_plus[k] += h;
    y_minus[k] -= h;
    system.state_derivative(0.0, y_plus, plus);
    system.state_derivative(0.0, y_minus, minus);
    jacobian.col(k) = (plus - minus) / (2.0 * h);
  }
  const Eigen::EigenSolver<MatrixX> solver(jacobian, false);
  StrokeLoopPoles result;
  result.largest_real_part = -std::numeric_limits<double>::infinity();
  for (int k = 0; k < n; ++k) {
    result.poles.push_back(solver.eigenvalues()[k]);
    result.largest_real_part = std::max(result.largest_real_part, solver.eigenvalues()[k].real());
  }
  return result;
}

std::string stable_gain_advice(const ActiveCompensatorParameters& active, double apparent_mass) {
  if (active.actuator == ActuatorType::force)
    return "e.g. by pole placement on the carried mass M: kp = M w^2, kd = 2 zeta M w, ki = 0.1 w kp "
           "(docs/physics/compensators.md §11)";
  const HydraulicCylinderParameters& c = active.hydraulic.cylinder;
  const double omega_h =
      std::sqrt(c.bulk_modulus * (c.area_a * c.area_a / c.volume_a + c.area_b * c.area_b / c.volume_b) / apparent_mass);
  return fmt::format("for a valve-driven cylinder a position-loop gain kp [1/s] well below 2 zeta_h "
                     "omega_h, with the hydraulic resonance omega_h = {:.3g} rad/s here and its damping "
                     "zeta_h from the valve's null leakage (valve.underlap) and cylinder leakage",
                     omega_h);
}

void check_stroke_loop_stable(const StrokeLoopPoles& poles, const ActiveCompensatorParameters& active,
                              double apparent_mass) {
  double scale = 1.0;
  for (const auto& pole : poles.poles) scale = std::max(scale, std::abs(pole));
  // Growth slower than one e-fold in 500 s is not flagged: a linearization across a
  // critically centred valve's null (a kink) resolves no better than that.
  if (!(poles.largest_real_part > std::max(1e-6 * scale, 2e-3))) return;
  std::complex<double> worst = poles.poles.front();
  for (const auto& pole : poles.poles)
    if (pole.real() > worst.real()) worst = pole;
  throw ParameterError(
      "controller",
      fmt::format("gains that make the stroke loop unstable: closed-loop pole at {:.4g} {} {:.4g}i 1/s (loop "
                  "linearized at the initial state with the {:.4g} kg carried along the stroke)",
                  worst.real(), worst.imag() < 0 ? "-" : "+", std::abs(worst.imag()), apparent_mass),
      "gains with every closed-loop pole in the left half-plane, " + stable_gain_advice(active, apparent_mass));
}

}  // namespace heavesim
