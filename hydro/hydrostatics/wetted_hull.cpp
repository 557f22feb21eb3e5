#include "hydro/hydrostatics/wetted_hull.hpp"

namespace heavesim::hydro {
namespace {

/// Surface integrals over the wetted part, accumulated triangle by triangle.
struct Integrals {
  double z_nz = 0, xz_nz = 0, yz_nz = 0, zz_nz = 0;  // int z n_z, x z n_z, y z n_z, z^2 n_z
  double nz = 0, x_nz = 0, y_nz = 0, xx_nz = 0, yy_nz = 0, xy_nz = 0;
  Vector3 z_n = Vector3::Zero();   // int z n dS
  Vector3 z_r_x_n = Vector3::Zero();  // int z (r x n) dS

  // On a flat triangle with vertex values f_i, g_i of linear functions:
  //   int f dS = A mean(f),  int f g dS = A/12 (sum f_i g_i + sum f_i sum g_i)
  // (int phi_i phi_j dS = A (1 + delta_ij) / 12 for the linear shape functions).
  void add_triangle(const Vector3& p0, const Vector3& p1, const Vector3& p2) {
    const Vector3 area_vector = 0.5 * (p1 - p0).cross(p2 - p0);  // n dS
    const double az = area_vector.z();
    const Vector3 sum = p0 + p1 + p2;
    auto product = [&](int a, int b) {
      return (p0[a] * p0[b] + p1[a] * p1[b] + p2[a] * p2[b] + sum[a] * sum[b]) / 12.0;  // int f g dS / A
    };
    const double mean_z = sum.z() / 3.0;
    z_nz += az * mean_z;
    xz_nz += az * product(0, 2);
    yz_nz += az * product(1, 2);
    zz_nz += az * product(2, 2);
    nz += az;
    x_nz += az * sum.x() / 3.0;
    y_nz += az * sum.y() / 3.0;
    xx_nz += az * product(0, 0);
    yy_nz += az * product(1, 1);
    xy_nz += az * product(0, 1);
    z_n += area_vector * mean_z;
    // int z r dS (a vector) crossed with the constant unit normal.
    const Vector3 z_r(product(2, 0), product(2, 1), product(2, 2));
    z_r_x_n += z_r.cross(area_vector);
  }
};

}  // namespace

WettedHull wetted_hull(const HullMesh& mesh, const Transform& X_world_body, double density, double gravity) {
  Integrals in;
  for (const HullPanel& panel : mesh.panels) {
    // Clip the polygon to z <= 0; a convex-or-not polygon of n vertices cut by one
    // plane keeps at most n + 1 vertices.
    std::array<Vector3, 5> clipped;
    int m = 0;
    Vector3 previous = X_world_body.act_point(panel.vertices[panel.num_vertices - 1]);
    for (int k = 0; k < panel.num_vertices; ++k) {
      const Vector3 current = X_world_body.act_point(panel.vertices[k]);
      const bool current_in = current.z() <= 0.0, previous_in = previous.z() <= 0.0;
      if (current_in != previous_in) {
        const double s = previous.z() / (previous.z() - current.z());
        Vector3 crossing = previous + s * (current - previous);
        crossing.z() = 0.0;
        clipped[m++] = crossing;
      }
      if (current_in) clipped[m++] = current;
      previous = current;
    }
    for (int k = 1; k + 1 < m; ++k) in.add_triangle(clipped[0], clipped[k], clipped[k + 1]);
  }
  WettedHull hull;
  hull.volume = in.z_nz;
  if (hull.volume > 0.0)
    hull.centre_of_buoyancy = Vector3(in.xz_nz, in.yz_nz, 0.5 * in.zz_nz) / hull.volume;
  hull.waterplane_area = -in.nz;
  hull.waterplane_first_moment = Eigen::Vector2d(-in.x_nz, -in.y_nz);
  hull.waterplane_second_moment << -in.xx_nz, -in.xy_nz, 0.0, -in.xy_nz, -in.yy_nz, 0.0, 0.0, 0.0, 0.0;
  const double rho_g = density * gravity;
  hull.buoyancy_force = rho_g * in.z_n;
  hull.buoyancy_moment = rho_g * in.z_r_x_n;
  return hull;
}

Eigen::Matrix<double, 6, 6> hydrostatic_stiffness(const WettedHull& h, double density, double gravity) {
  const double rho_g = density * gravity;
  const Vector3& b = h.centre_of_buoyancy;
  Eigen::Matrix<double, 6, 6> C = Eigen::Matrix<double, 6, 6>::Zero();
  C(2, 2) = rho_g * h.waterplane_area;
  C(2, 3) = C(3, 2) = rho_g * h.waterplane_first_moment.y();
  C(2, 4) = C(4, 2) = -rho_g * h.waterplane_first_moment.x();
  C(3, 3) = rho_g * (h.waterplane_second_moment(1, 1) + h.volume * b.z());
  C(3, 4) = C(4, 3) = -rho_g * h.waterplane_second_moment(0, 1);
  C(4, 4) = rho_g * (h.waterplane_second_moment(0, 0) + h.volume * b.z());
  C(3, 5) = -rho_g * h.volume * b.x();
  C(4, 5) = -rho_g * h.volume * b.y();
  return C;
}

}  // namespace heavesim::hydro
