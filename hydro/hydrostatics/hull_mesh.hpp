#pragma once
// Hull surface as flat panels (triangles or quadrilaterals) in the body frame [m].
// Vertices run counter-clockwise seen from the water, so (v1 - v0) x (v2 - v0) points
// out of the hull, into the fluid (WAMIT .gdf convention).
#include <array>
#include <string>
#include <vector>

#include "kernel/spatial/types.hpp"

namespace heavesim::hydro {

struct HullPanel {
  std::array<Vector3, 4> vertices{Vector3::Zero(), Vector3::Zero(), Vector3::Zero(), Vector3::Zero()};  // m, body frame; the first num_vertices are used
  int num_vertices = 4;             // 3 or 4
};

struct HullMesh {
  std::vector<HullPanel> panels;
  void append(const HullMesh& other) { panels.insert(panels.end(), other.panels.begin(), other.panels.end()); }
};

/// Closed box with edges along the body axes: size (Lx, Ly, Lz) [m], centred at
/// `centre` [m, body frame]; each face split into divisions x divisions quads.
HullMesh box_mesh(const Vector3& size, const Vector3& centre = Vector3::Zero(), int divisions = 1);

/// Closed vertical cylinder (axis along body z) of radius r [m] from z_bottom to z_top
/// [m], its axis through (x, y) = axis_xy, as a prism on a regular polygon of
/// num_sides sides inscribed in the circle (so its exact volume is the prism's).
HullMesh vertical_cylinder_mesh(double radius, double z_bottom, double z_top, int num_sides,
                                const Eigen::Vector2d& axis_xy = Eigen::Vector2d::Zero());

/// The mesh mirrored in the plane x = 0 (axis 0) or y = 0 (axis 1), vertex order
/// reversed so the normals still point into the fluid.
HullMesh mirrored(const HullMesh& mesh, int axis);

/// WAMIT low-order geometry file (.gdf): header line, "ULEN GRAV", "ISX ISY", NPAN, then
/// 4 vertices (12 numbers) per panel, free format (WAMIT User Manual sec. 6.1). Vertices
/// are scaled by ULEN; ISX = 1 (ISY = 1) adds the mirror image in x = 0 (y = 0), so the
/// returned mesh is the whole hull. A panel with two equal vertices is a triangle.
/// Throws DataError naming the file and line.
HullMesh read_gdf(const std::string& path);

/// STL (ASCII or binary) triangles, normals from the vertex order (STL's right-hand
/// rule, outward). Throws DataError.
HullMesh read_stl(const std::string& path);

}  // namespace heavesim::hydro
