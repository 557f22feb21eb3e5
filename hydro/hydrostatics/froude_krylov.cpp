#include "hydro/hydrostatics/froude_krylov.hpp"

#include <cmath>

namespace heavesim::hydro {
namespace {

/// Incident-wave dynamic pressure head (p_dyn / rho g) at (x, y, z) with Wheeler stretching.
double dynamic_head(const WaveTrain& waves, double ramp, double t, const Vector3& p, double eta) {
  double head = 0.0;
  const double z_stretched = p.z() - eta;
  for (const WaveComponent& c : waves.components())
    head += c.amplitude * std::exp(c.wave_number * z_stretched) *
            std::cos(c.angular_frequency * t - c.wave_number * (p.x() * std::cos(c.heading) + p.y() * std::sin(c.heading)) +
                     c.phase);
  return ramp * head;
}

// Dunavant's degree-5 rule: barycentric points and weights (sum 1).
constexpr double a1 = 0.059715871789770, b1 = 0.470142064105115, a2 = 0.797426985353087, b2 = 0.101286507323456;
constexpr double w0 = 0.225, w1 = 0.132394152788506, w2 = 0.125939180544827;

}  // namespace

FroudeKrylovLoad froude_krylov_load(const HullMesh& mesh, const Transform& X_world_body, const WaveTrain& waves, double t,
                                    double density, double gravity) {
  FroudeKrylovLoad load;
  const double ramp = waves.ramp()(t), rho_g = density * gravity;
  for (const HullPanel& panel : mesh.panels) {
    std::array<Vector3, 4> world;
    std::array<double, 4> height;  // z - eta at each vertex
    for (int k = 0; k < panel.num_vertices; ++k) {
      world[k] = X_world_body.act_point(panel.vertices[k]);
      height[k] = world[k].z() - waves.elevation(t, world[k].x(), world[k].y());
    }
    std::array<Vector3, 5> clipped;
    int m = 0;
    for (int k = 0; k < panel.num_vertices; ++k) {
      const int previous = (k + panel.num_vertices - 1) % panel.num_vertices;
      const bool in = height[k] <= 0.0, previous_in = height[previous] <= 0.0;
      if (in != previous_in) {
        const double s = height[previous] / (height[previous] - height[k]);
        clipped[m++] = world[previous] + s * (world[k] - world[previous]);
      }
      if (in) clipped[m++] = world[k];
    }
    for (int k = 1; k + 1 < m; ++k) {
      const Vector3 &p0 = clipped[0], &p1 = clipped[k], &p2 = clipped[k + 1];
      const Vector3 area_vector = 0.5 * (p1 - p0).cross(p2 - p0);  // n dS
      load.wetted_area += area_vector.norm();
      const std::array<Vector3, 7> points = {
          (p0 + p1 + p2) / 3.0,
          a1 * p0 + b1 * p1 + b1 * p2, b1 * p0 + a1 * p1 + b1 * p2, b1 * p0 + b1 * p1 + a1 * p2,
          a2 * p0 + b2 * p1 + b2 * p2, b2 * p0 + a2 * p1 + b2 * p2, b2 * p0 + b2 * p1 + a2 * p2};
      const std::array<double, 7> weights = {w0, w1, w1, w1, w2, w2, w2};
      double pressure_integral = 0.0;  // int p dS / |n dS| -> weights sum to 1
      Vector3 pressure_moment = Vector3::Zero();  // int p r dS likewise
      for (int q = 0; q < 7; ++q) {
        const Vector3& r = points[q];
        const double eta = waves.elevation(t, r.x(), r.y());
        const double p = rho_g * (-r.z() + dynamic_head(waves, ramp, t, r, eta));
        pressure_integral += weights[q] * p;
        pressure_moment += weights[q] * p * r;
      }
      // F = -int p n dS, M = -int r x n p dS = -(int p r dS) x n.
      load.force -= pressure_integral * area_vector;
      load.moment -= pressure_moment.cross(area_vector);
    }
  }
  return load;
}

}  // namespace heavesim::hydro
