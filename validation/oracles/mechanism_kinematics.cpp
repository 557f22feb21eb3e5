#include "validation/oracles/mechanism_kinematics.hpp"

#include <cmath>

namespace heavesim::oracle {

Motion3 slider_crank_crank_angle(double r, double l, const Motion3& x) {
  const double X = x.position;
  const double c = X / (2 * r) + (r * r - l * l) / (2 * r * X);
  const double c_x = 1 / (2 * r) - (r * r - l * l) / (2 * r * X * X);
  const double c_xx = (r * r - l * l) / (r * X * X * X);
  const double c_dot = c_x * x.velocity;
  const double c_ddot = c_xx * x.velocity * x.velocity + c_x * x.acceleration;
  Motion3 theta;
  theta.position = std::acos(c);
  const double s = std::sin(theta.position);
  theta.velocity = -c_dot / s;
  theta.acceleration = -(c_ddot + c * theta.velocity * theta.velocity) / s;
  return theta;
}

DrivenSliderCrank driven_slider_crank(double r, double l, double crank_inertia, double block_mass,
                                      const Motion3& theta) {
  const double s = std::sin(theta.position), c = std::cos(theta.position);
  const double D = std::sqrt(l * l - r * r * s * s);
  DrivenSliderCrank result;
  result.x = r * c + D;
  result.x_theta = -r * s - r * r * s * c / D;
  result.x_thetatheta = -r * c - r * r * (c * c - s * s) / D - std::pow(r, 4) * s * s * c * c / (D * D * D);
  result.torque = crank_inertia * theta.acceleration +
                  block_mass * result.x_theta *
                      (result.x_theta * theta.acceleration + result.x_thetatheta * theta.velocity * theta.velocity);
  return result;
}

FourBarAngles four_bar_angles(double a, double b, double c, double d, const Motion3& crank, int branch) {
  using Eigen::Vector2d;
  const double t2 = crank.position, w2 = crank.velocity, al2 = crank.acceleration;
  const Vector2d A(a * std::cos(t2), a * std::sin(t2)), O4(d, 0.0);
  // Circle-circle intersection: along the line A -> O4 at distance p from A, offset h.
  const Vector2d to_O4 = O4 - A;
  const double e = to_O4.norm();
  const Vector2d u = to_O4 / e, perpendicular(-u.y(), u.x());
  const double p = (b * b - c * c + e * e) / (2 * e);
  const double h = std::sqrt(b * b - p * p);
  Vector2d B = A + p * u + h * perpendicular;
  const auto cross = [](const Vector2d& x, const Vector2d& y) { return x.x() * y.y() - x.y() * y.x(); };
  if (cross(A - O4, B - O4) * branch < 0) B = A + p * u - h * perpendicular;
  const double t3 = std::atan2(B.y() - A.y(), B.x() - A.x());
  const double t4 = std::atan2(B.y() - O4.y(), B.x() - O4.x());
  // Loop closure a e(t2) + b e(t3) = d e_x + c e(t4); with e'(t) = n(t) = (-sin, cos):
  //   b w3 n3 - c w4 n4 = -a w2 n2,
  //   b al3 n3 - c al4 n4 = -a al2 n2 + a w2^2 e2 + b w3^2 e3 - c w4^2 e4.
  const Vector2d e2(std::cos(t2), std::sin(t2)), e3(std::cos(t3), std::sin(t3)), e4(std::cos(t4), std::sin(t4));
  const Vector2d n2(-e2.y(), e2.x()), n3(-e3.y(), e3.x()), n4(-e4.y(), e4.x());
  const Vector2d col3 = b * n3, col4 = -c * n4;
  const double det = cross(col3, col4);
  const auto solve = [&](const Vector2d& rhs) {  // Cramer's rule for [col3 col4] (x3, x4) = rhs
    return Vector2d(cross(rhs, col4) / det, cross(col3, rhs) / det);
  };
  const Vector2d w = solve(-a * w2 * n2);
  const Vector2d al = solve(-a * al2 * n2 + a * w2 * w2 * e2 + b * w.x() * w.x() * e3 - c * w.y() * w.y() * e4);
  FourBarAngles result;
  result.coupler = {t3, w.x(), al.x()};
  result.rocker = {t4, w.y(), al.y()};
  return result;
}

}  // namespace heavesim::oracle
