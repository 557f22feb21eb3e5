#pragma once
// Oracle for validation A05 (IFToMM benchmark A05, the stiff flyball governor;
// docs/physics/benchmarks.md): the governor reduced to its symmetric motion in two
// coordinates and a cyclic one, written from Lagrange's equations alone.
//
// Coordinates: theta, both arms' angle below the horizontal (the two arms move as mirror
// images: the 180-degree symmetry about the shaft keeps them so), s, the slider centre's
// height on the shaft, and the shaft angle phi, which is cyclic (no torque on the shaft,
// the spring-dampers are internal): p = J(theta) phi' is conserved, so phi' = p / J(theta).
// With e the pin offset from the axis, h the pin height, c = L/2 the rod's centre, L the
// rod length:
//   J(theta) = I_shaft + I_slider + 2 [ I_axial sin^2 + I_transverse cos^2
//                                       + m_rod (e + c cos)^2 + m_ball (e + L cos)^2 ]
//   T = 1/2 a theta'^2 + 1/2 m_slider s'^2 + 1/2 J(theta) phi'^2,
//       a = 2 (I_transverse + m_rod c^2 + m_ball L^2)
//   V = -2 g sin(theta) (m_rod c + m_ball L) + m_slider g s   (+ constants)
// and each spring-damper, from the slider's side (e, s) to the rod's centre
// (e + c cos, h - c sin) in the arms' plane, pulls with F = k (l - l0) + d l' along its
// line: generalized forces Q_theta = -2 F dl/dtheta, Q_s = -2 F dl/ds. Then
//   a theta'' = 1/2 J'(theta) phi'^2 + 2 g cos(theta) (m_rod c + m_ball L) + Q_theta,
//   m_slider s'' = -m_slider g + Q_s.
// Integrated by ARKODE Fehlberg 8(7) (reference_integrator): shares nothing with the kernel.
#include <vector>

namespace heavesim::oracle {

struct FlyballGovernorParameters {
  double gravity = 9.81;                                                  // m/s^2, along the shaft, downwards
  double pin_offset = 0.05;                                               // m, e: pins and spring ends off the axis
  double pin_height = 1.0;                                                // m, h: the pins on the shaft's top
  double rod_length = 1.0;                                                // m, L
  double rod_section = 0.01;                                              // m, side of the rods' square section
  double rod_mass = 3000.0 * 1.0 * 0.01 * 0.01;                           // kg, 1 x 0.01 x 0.01 m at 3000 kg/m^3
  double ball_mass = 5.0;                                                 // kg, point mass at the rod's end
  double slider_mass = 3000.0 * 0.1 * 0.1 * 0.1;                          // kg, 0.1 m cube
  double shaft_axial_inertia = 0.3 * (0.01 * 0.01 + 0.01 * 0.01) / 12.0;  // kg m^2
  double slider_axial_inertia = 3.0 * (0.1 * 0.1 + 0.1 * 0.1) / 12.0;     // kg m^2
  double stiffness = 8e5;                                                 // N/m
  double damping = 4e4;                                                   // N s/m
  double rest_length = 0.5;                                               // m
  // Initial state: theta0 = 30 degrees (springs at rest), s0 = 0.5 m, shaft at 2 pi rad/s.
  double theta0 = 0.52359877559829887;     // rad
  double slider_height0 = 0.5;             // m
  double spin_rate0 = 6.2831853071795865;  // rad/s
};

struct FlyballGovernorState {
  double arm_angle = 0.0;      // rad, theta, below the horizontal
  double arm_rate = 0.0;       // rad/s
  double slider_height = 0.0;  // m, s
  double slider_rate = 0.0;    // m/s
  double spin_rate = 0.0;      // rad/s, phi' = p / J(theta)
};

/// The state at each time [s] (ascending, > 0), from rest relative to the spinning shaft.
std::vector<FlyballGovernorState> flyball_governor_states(const FlyballGovernorParameters& parameters,
                                                          const std::vector<double>& times, double tolerance);

}  // namespace heavesim::oracle
