#pragma once
// Exact hydrostatics of a panel hull cut by the still-water plane z = 0 (world frame,
// z up): each panel is clipped to z <= 0 (Sutherland-Hodgman against one plane) and
// the surface integrals below are evaluated exactly on the clipped polygons (the
// integrands are polynomials of degree <= 2 on flat panels). The waterplane lid is
// never built: with the divergence theorem its contributions follow from the wetted
// surface alone (n outward from the hull, S_w the wetted surface):
//   V            = int_Sw z n_z dS                       (div(z e_z) = 1; z = 0 on the lid)
//   V x_B, V y_B = int_Sw x z n_z dS, int_Sw y z n_z dS
//   V z_B        = int_Sw z^2/2 n_z dS
//   A_wp         = -int_Sw n_z dS,  int_wp f dA = -int_Sw f n_z dS for f(x, y) (div(f e_z) = 0)
//   buoyancy     F = int_Sw rho g z n dS  (p = -rho g z),  M_O = int_Sw r x (rho g z n) dS.
// Below-water only: an unclosed mesh (no deck) is fine as long as it is closed below
// z = 0, like a WAMIT .gdf cut at the waterline.
#include "hydro/hydrostatics/hull_mesh.hpp"
#include "kernel/spatial/transform.hpp"

namespace heavesim::hydro {

struct WettedHull {
  double volume = 0.0;                            // V [m^3]
  Vector3 centre_of_buoyancy = Vector3::Zero();   // [m], world frame
  double waterplane_area = 0.0;                   // A_wp [m^2]
  Eigen::Vector2d waterplane_first_moment = Eigen::Vector2d::Zero();  // int (x, y) dA [m^3], world
  Matrix3 waterplane_second_moment = Matrix3::Zero();  // [m^4], world: (0,0) int x^2, (1,1) int y^2, (0,1) int x y
  Vector3 buoyancy_force = Vector3::Zero();       // F [N], world frame (rho g V e_z for a closed hull)
  Vector3 buoyancy_moment = Vector3::Zero();      // M [N m] about the world origin, world frame
};

/// The hull `mesh` (body frame) placed at X_world_body, cut at z = 0, in water of
/// density rho [kg/m^3] under gravity g [m/s^2]. Allocates nothing.
WettedHull wetted_hull(const HullMesh& mesh, const Transform& X_world_body, double density, double gravity);

/// Linear hydrostatic restoring matrix [WAMIT order: surge, sway, heave, roll, pitch,
/// yaw; N/m, N, N m/rad] about the world origin, buoyancy and waterplane only (gravity
/// is the kernel's): WAMIT User Manual eq. 3.1 without the m g terms,
///   C33 = rho g A_wp, C34 = rho g int y dA, C35 = -rho g int x dA,
///   C44 = rho g (int y^2 dA + V z_B), C45 = -rho g int x y dA, C55 = rho g (int x^2 dA + V z_B),
///   C46 = -rho g V x_B, C56 = -rho g V y_B, and the transposes of the 3-4, 3-5, 4-5 terms.
Eigen::Matrix<double, 6, 6> hydrostatic_stiffness(const WettedHull& hull, double density, double gravity);

}  // namespace heavesim::hydro
