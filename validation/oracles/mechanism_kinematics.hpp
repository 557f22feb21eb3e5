#pragma once
// Closed-form kinematics and inverse dynamics of the planar mechanisms of validation
// rows L3, L6 and L8, written from the loop-closure equations alone (Haug 1989, ch. 5;
// Uicker, Pennock & Shigley, Theory of Machines and Mechanisms, ch. 4-5), with no
// kernel code: positions by triangle geometry, velocities and accelerations by the
// exact time derivatives of the loop closure.
#include <Eigen/Core>

namespace heavesim::oracle {

/// A scalar and its first two time derivatives.
struct Motion3 {
  double position = 0.0, velocity = 0.0, acceleration = 0.0;
};

/// Slider-crank with the block driven: crank radius r about the origin, rod of length l
/// from the crank pin to the block at (x, 0). The crank angle on the branch sin > 0:
///   cos(theta) = (x^2 + r^2 - l^2) / (2 r x),
/// and its derivatives from c(x) = x / (2r) + (r^2 - l^2) / (2 r x):
///   c' = c_x x',  c'' = c_xx x'^2 + c_x x'',  theta' = -c' / sin,
///   theta'' = -(c'' + cos theta'^2) / sin.
Motion3 slider_crank_crank_angle(double r, double l, const Motion3& x);

/// Slider-crank with the crank driven: block position x(theta) = r cos + sqrt(l^2 - r^2 sin^2)
/// and the torque on the crank for a crank of inertia I_c about its pivot, a massless rod
/// and a block of mass m translating on x (Lagrange, T = (I_c + m x_theta^2) theta'^2 / 2):
///   tau = I_c theta'' + m x_theta (x_theta theta'' + x_thetatheta theta'^2).
struct DrivenSliderCrank {
  double x = 0.0, x_theta = 0.0, x_thetatheta = 0.0;  // m, m/rad, m/rad^2
  double torque = 0.0;                                 // N m
};
DrivenSliderCrank driven_slider_crank(double r, double l, double crank_inertia, double block_mass,
                                      const Motion3& theta);

/// Four-bar: ground pivots O2 = (0, 0) and O4 = (d, 0); crank a (angle theta2 from x),
/// coupler b, rocker c (angle theta4 of O4 -> B). B is the intersection of the circles
/// |B - A| = b and |B - O4| = c on the side where (A - O4) x (B - O4) has the sign of
/// `branch` (+1 or -1). Angles of the coupler (theta3, A -> B) and rocker and their
/// derivatives from the velocity and acceleration loop equations (2x2, Cramer).
struct FourBarAngles {
  Motion3 coupler, rocker;  // rad, rad/s, rad/s^2 (absolute angles from the x axis)
};
FourBarAngles four_bar_angles(double a, double b, double c, double d, const Motion3& crank, int branch);

}  // namespace heavesim::oracle
