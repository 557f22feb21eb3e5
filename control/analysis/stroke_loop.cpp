#include "control/analysis/stroke_loop.hpp"

#include <Eigen/Eigenvalues>

#include "kernel/elements/point_force.hpp"
#include "kernel/model/model_builder.hpp"
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

}  // namespace heavesim
