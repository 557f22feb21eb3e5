#include "validation/oracles/slider_crank.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "validation/oracles/reference_integrator.hpp"

namespace heavesim::oracle {
namespace {

struct Coordinates {
  Eigen::Vector3d s, B, dB;  // (theta, x, phi), ds/dtheta, d2s/dtheta2
};

Coordinates coordinates(const SliderCrankParameters& p, double theta) {
  const double s1 = std::sin(theta), c1 = std::cos(theta);
  const double phi = std::asin(-p.a * s1);
  const double s2 = std::sin(phi), c2 = std::cos(phi);
  const double dphi = -p.a * c1 / c2;
  const double ddphi = p.a * (s1 * c2 - c1 * s2 * dphi) / (c2 * c2);
  Coordinates out;
  out.s << theta, p.a * c1 + c2, phi;
  out.B << 1.0, -p.a * s1 - s2 * dphi, dphi;
  out.dB << 0.0, -p.a * c1 - c2 * dphi * dphi - s2 * ddphi, ddphi;
  return out;
}

/// Generalized forces on (theta, x, phi) for positions s and rates sd.
Eigen::Vector3d generalized_forces(const SliderCrankParameters& p, const Eigen::Vector3d& s, const Eigen::Vector3d& sd) {
  const double s1 = std::sin(s[0]), c1 = std::cos(s[0]), s2 = std::sin(s[2]), c2 = std::cos(s[2]);
  // Point Jacobians (rows x, y; columns theta, x, phi).
  Eigen::Matrix<double, 2, 3> crank_mid, rod_mid, push_point;
  crank_mid << -0.5 * p.a * s1, 0, 0, 0.5 * p.a * c1, 0, 0;
  rod_mid << 0, 1, 0.5 * s2, 0, 0, -0.5 * c2;
  push_point << 0, 1, -s2, 0, 0, c2;
  const Eigen::Vector2d crank_mid_position(0.5 * p.a * c1, 0.5 * p.a * s1);
  const Eigen::Vector2d rod_mid_position(s[1] - 0.5 * c2, -0.5 * s2);
  const Eigen::Vector2d d = rod_mid_position - crank_mid_position;
  const double length = d.norm();
  const double rate = d.dot((rod_mid - crank_mid) * sd) / length;
  const double tension = p.k * (length - p.l0) + p.c * rate;
  const Eigen::Vector2d on_rod = -tension * d / length;
  return rod_mid.transpose() * on_rod - crank_mid.transpose() * on_rod +
         push_point.transpose() * Eigen::Vector2d(p.F, 0.0);
}

}  // namespace

std::vector<Eigen::Vector3d> slider_crank_positions(const SliderCrankParameters& p, const std::vector<double>& times,
                                                    double tolerance) {
  const Eigen::Vector3d mass(p.J1, p.m2, p.J2);
  const Rhs rhs = [&](double, const Eigen::VectorXd& y, Eigen::VectorXd& ydot) {
    const Coordinates c = coordinates(p, y[0]);
    const Eigen::Vector3d Q = generalized_forces(p, c.s, c.B * y[1]);
    const double inertia = c.B.dot(mass.cwiseProduct(c.B));
    ydot.resize(2);
    ydot[0] = y[1];
    ydot[1] = (c.B.dot(Q) - c.B.dot(mass.cwiseProduct(c.dB)) * y[1] * y[1]) / inertia;
  };
  const std::vector<Eigen::VectorXd> states =
      integrate_reference(rhs, 0.0, Eigen::Vector2d(M_PI / 2, 0.0), times, tolerance, tolerance);
  std::vector<Eigen::Vector3d> positions;
  for (const Eigen::VectorXd& y : states) positions.push_back(coordinates(p, y[0]).s);
  return positions;
}

std::vector<std::pair<double, Eigen::Vector3d>> read_ida_slider_crank_printout(const std::string& path) {
  std::vector<std::pair<double, Eigen::Vector3d>> rows;
  std::ifstream file(path);
  std::string line;
  while (std::getline(file, line)) {
    std::istringstream fields(line);
    double t, y1, y2, y3, steps, order, h;
    std::string rest;
    if (fields >> t >> y1 >> y2 >> y3 >> steps >> order >> h && !(fields >> rest))
      rows.emplace_back(t, Eigen::Vector3d(y1, y2, y3));
  }
  return rows;
}

}  // namespace heavesim::oracle
