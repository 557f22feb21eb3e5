#include "validation/oracles/bricard_mechanism.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <array>
#include <cmath>

#include "validation/oracles/reference_integrator.hpp"

namespace heavesim::oracle {
namespace {

constexpr int joints = 5;
constexpr double gravity = 9.81;  // m/s^2 along -y
constexpr double rod_mass = 1.0;  // kg

// Rod j hangs on joint j; joint j sits at offset[j] in rod j-1's frame (ground for j = 0)
// and turns about axis[j] (rod j-1's axes). Rod frames start parallel to the world.
const std::array<Eigen::Vector3d, joints> offset = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0),
                                                    Eigen::Vector3d(0, -1, 0), Eigen::Vector3d(0, 0, 1),
                                                    Eigen::Vector3d(-1, 0, 0)};
const std::array<Eigen::Vector3d, joints> axis = {Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(),
                                                  Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                                                  Eigen::Vector3d::UnitZ()};
const std::array<Eigen::Vector3d, joints> centre = {Eigen::Vector3d(0.5, 0, 0), Eigen::Vector3d(0, -0.5, 0),
                                                    Eigen::Vector3d(0, 0, 0.5), Eigen::Vector3d(-0.5, 0, 0),
                                                    Eigen::Vector3d(0, 0.5, 0)};
// A 1 m rod with a 0.1 m square section: m (L^2 + a^2)/12 across, m a^2/6 along (rod frame).
Eigen::Matrix3d rod_inertia(int rod) {
  const double across = rod_mass * (1.0 + 0.01) / 12.0, along = rod_mass * 0.01 / 6.0;
  Eigen::Vector3d diagonal = Eigen::Vector3d::Constant(across);
  const int long_axis = rod == 0 || rod == 3 ? 0 : (rod == 1 || rod == 4 ? 1 : 2);
  diagonal[long_axis] = along;
  return diagonal.asDiagonal();
}
// The closure (sixth joint): rod 5's point (0, 1, 0) on E = (0, 0, 1), its x axis along the world x.
const Eigen::Vector3d closure_point_on_rod5(0, 1, 0);
const Eigen::Vector3d closure_point_on_ground(0, 0, 1);

struct Pose {
  std::array<Eigen::Matrix3d, joints> rotation;  // rod j's axes in the world
  std::array<Eigen::Vector3d, joints> origin;    // joint j (rod j's frame origin), world
  std::array<Eigen::Vector3d, joints> world_axis;
};

Pose pose(const Eigen::VectorXd& x) {
  Pose result;
  Eigen::Matrix3d parent_rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d parent_origin = Eigen::Vector3d::Zero();
  for (int j = 0; j < joints; ++j) {
    result.origin[j] = parent_origin + parent_rotation * offset[j];
    result.world_axis[j] = parent_rotation * axis[j];
    result.rotation[j] = parent_rotation * Eigen::AngleAxisd(x[j], axis[j]).toRotationMatrix();
    parent_rotation = result.rotation[j];
    parent_origin = result.origin[j];
  }
  return result;
}

// Linear and angular velocity Jacobians (3 x 5) of a point r fixed to rod `rod`.
void point_jacobian(const Pose& p, int rod, const Eigen::Vector3d& r, Eigen::Matrix<double, 3, joints>& linear,
                    Eigen::Matrix<double, 3, joints>& angular) {
  linear.setZero();
  angular.setZero();
  for (int j = 0; j <= rod; ++j) {
    linear.col(j) = p.world_axis[j].cross(r - p.origin[j]);
    angular.col(j) = p.world_axis[j];
  }
}

Eigen::MatrixXd mass_matrix(const Eigen::VectorXd& x) {
  const Pose p = pose(x);
  Eigen::MatrixXd mass = Eigen::MatrixXd::Zero(joints, joints);
  Eigen::Matrix<double, 3, joints> linear, angular;
  for (int rod = 0; rod < joints; ++rod) {
    point_jacobian(p, rod, p.origin[rod] + p.rotation[rod] * centre[rod], linear, angular);
    const Eigen::Matrix3d inertia_world = p.rotation[rod] * rod_inertia(rod) * p.rotation[rod].transpose();
    mass += rod_mass * linear.transpose() * linear + angular.transpose() * inertia_world * angular;
  }
  return mass;
}

// Generalized gravity forces Q = -dV/dx, V = sum m g y_centre.
Eigen::VectorXd gravity_forces(const Eigen::VectorXd& x) {
  const Pose p = pose(x);
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(joints);
  Eigen::Matrix<double, 3, joints> linear, angular;
  for (int rod = 0; rod < joints; ++rod) {
    point_jacobian(p, rod, p.origin[rod] + p.rotation[rod] * centre[rod], linear, angular);
    forces += linear.transpose() * Eigen::Vector3d(0, -rod_mass * gravity, 0);
  }
  return forces;
}

double potential_energy(const Eigen::VectorXd& x) {
  const Pose p = pose(x);
  double energy = 0.0;
  for (int rod = 0; rod < joints; ++rod)
    energy += rod_mass * gravity * (p.origin[rod] + p.rotation[rod] * centre[rod]).y();
  return energy;
}

Eigen::VectorXd closure(const Eigen::VectorXd& x) {
  const Pose p = pose(x);
  Eigen::VectorXd phi(5);
  phi.head<3>() = p.origin[4] + p.rotation[4] * closure_point_on_rod5 - closure_point_on_ground;
  const Eigen::Vector3d rod5_x = p.rotation[4].col(0);
  phi[3] = rod5_x.y();
  phi[4] = rod5_x.z();
  return phi;
}

Eigen::MatrixXd closure_jacobian(const Eigen::VectorXd& x) {
  const Pose p = pose(x);
  Eigen::Matrix<double, 3, joints> linear, angular;
  point_jacobian(p, 4, p.origin[4] + p.rotation[4] * closure_point_on_rod5, linear, angular);
  Eigen::MatrixXd jacobian(5, joints);
  jacobian.topRows<3>() = linear;
  const Eigen::Vector3d rod5_x = p.rotation[4].col(0);
  for (int j = 0; j < joints; ++j) {
    const Eigen::Vector3d rate = angular.col(j).cross(rod5_x);  // d(rod5_x)/dx_j
    jacobian(3, j) = rate.y();
    jacobian(4, j) = rate.z();
  }
  return jacobian;
}

// Central difference of a matrix function along direction d: (F(x + h d) - F(x - h d)) / 2h.
template <class Function>
Eigen::MatrixXd directional_difference(const Function& f, const Eigen::VectorXd& x, const Eigen::VectorXd& d) {
  const double step = 1e-5 / std::max(1.0, d.norm());
  return (f(x + step * d) - f(x - step * d)) / (2.0 * step);
}

Eigen::VectorXd accelerations(const Eigen::VectorXd& x, const Eigen::VectorXd& rate) {
  const Eigen::MatrixXd mass = mass_matrix(x);
  // c = M' x' - 1/2 d(x'^T M x')/dx.
  Eigen::VectorXd velocity_terms = directional_difference(mass_matrix, x, rate) * rate;
  for (int j = 0; j < joints; ++j) {
    const Eigen::VectorXd unit = Eigen::VectorXd::Unit(joints, j);
    velocity_terms[j] -= 0.5 * rate.dot(directional_difference(mass_matrix, x, unit) * rate);
  }
  const Eigen::MatrixXd jacobian = closure_jacobian(x);
  const Eigen::VectorXd jacobian_rate_times_rate = directional_difference(closure_jacobian, x, rate) * rate;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(jacobian, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::JacobiSVD<Eigen::MatrixXd> pseudo_inverse_solver(jacobian, Eigen::ComputeThinU | Eigen::ComputeThinV);
  pseudo_inverse_solver.setThreshold(1e-10);
  const Eigen::VectorXd particular = -pseudo_inverse_solver.solve(jacobian_rate_times_rate);  // J x''_p = -J' x'
  const Eigen::VectorXd null_direction = svd.matrixV().col(joints - 1);                       // rank 4 of 5
  const Eigen::VectorXd force = gravity_forces(x) - velocity_terms - mass * particular;
  const double modal_mass = null_direction.dot(mass * null_direction);
  return particular + null_direction * (null_direction.dot(force) / modal_mass);
}

}  // namespace

std::vector<BricardSample> bricard_samples(const std::vector<double>& times, double tolerance) {
  const Rhs rhs = [](double, const Eigen::VectorXd& y, Eigen::VectorXd& ydot) {
    const Eigen::VectorXd x = y.head(joints), rate = y.tail(joints);
    ydot.head(joints) = rate;
    ydot.tail(joints) = accelerations(x, rate);
  };
  const std::vector<Eigen::VectorXd> states =
      integrate_reference(rhs, 0.0, Eigen::VectorXd::Zero(2 * joints), times, tolerance, tolerance);
  std::vector<BricardSample> samples;
  samples.reserve(states.size());
  for (const Eigen::VectorXd& state : states) {
    const Eigen::VectorXd x = state.head(joints), rate = state.tail(joints);
    BricardSample sample;
    sample.p3 = pose(x).origin[2];
    sample.energy = 0.5 * rate.dot(mass_matrix(x) * rate) + potential_energy(x);
    sample.closure_residual = closure(x).cwiseAbs().maxCoeff();
    samples.push_back(sample);
  }
  return samples;
}

}  // namespace heavesim::oracle
