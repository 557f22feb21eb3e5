#include "hydro/hydrostatics/hull_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

#include "hydro/data_error.hpp"
#include "hydro/data_file.hpp"

namespace heavesim::hydro {
namespace {

HullPanel quad(const Vector3& a, const Vector3& b, const Vector3& c, const Vector3& d) { return {{a, b, c, d}, 4}; }

}  // namespace

HullMesh box_mesh(const Vector3& size, const Vector3& centre, int divisions) {
  HullMesh mesh;
  const int n = std::max(1, divisions);
  // Each face: outward normal along +-axis a; (u, v) the other axes ordered so that
  // e_u x e_v = +e_a, then the vertex order (0,0),(1,0),(1,1),(0,1) faces outward.
  for (int a = 0; a < 3; ++a) {
    for (int side : {-1, 1}) {
      int u = (a + 1) % 3, v = (a + 2) % 3;
      if (side < 0) std::swap(u, v);
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          auto corner = [&](int di, int dj) {
            Vector3 p = centre;
            p[a] += 0.5 * side * size[a];
            p[u] += size[u] * (-0.5 + double(i + di) / n);
            p[v] += size[v] * (-0.5 + double(j + dj) / n);
            return p;
          };
          mesh.panels.push_back(quad(corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)));
        }
    }
  }
  return mesh;
}

HullMesh vertical_cylinder_mesh(double radius, double z_bottom, double z_top, int num_sides,
                                const Eigen::Vector2d& axis_xy) {
  HullMesh mesh;
  auto rim = [&](int i, double z) {
    const double angle = 2.0 * M_PI * i / num_sides;
    return Vector3(axis_xy.x() + radius * std::cos(angle), axis_xy.y() + radius * std::sin(angle), z);
  };
  const Vector3 bottom_centre(axis_xy.x(), axis_xy.y(), z_bottom), top_centre(axis_xy.x(), axis_xy.y(), z_top);
  for (int i = 0; i < num_sides; ++i) {
    mesh.panels.push_back(quad(rim(i, z_bottom), rim(i + 1, z_bottom), rim(i + 1, z_top), rim(i, z_top)));
    mesh.panels.push_back({{bottom_centre, rim(i + 1, z_bottom), rim(i, z_bottom), Vector3::Zero()}, 3});
    mesh.panels.push_back({{top_centre, rim(i, z_top), rim(i + 1, z_top), Vector3::Zero()}, 3});
  }
  return mesh;
}

HullMesh mirrored(const HullMesh& mesh, int axis) {
  HullMesh result = mesh;
  for (HullPanel& panel : result.panels) {
    for (int k = 0; k < panel.num_vertices; ++k) panel.vertices[k][axis] = -panel.vertices[k][axis];
    std::reverse(panel.vertices.begin(), panel.vertices.begin() + panel.num_vertices);
  }
  return result;
}

namespace {

/// Whitespace-separated numbers of a text file with the line each came from.
struct NumberReader {
  std::string path;
  std::ifstream in;
  std::istringstream line_stream;
  int line = 0;

  explicit NumberReader(std::string p) : path(std::move(p)) {
    require_readable_data_file(path, "hull mesh");  // before open(): a FIFO's open blocks
    in.open(path);
    if (!in) throw DataError(path, 0, "a file that cannot be opened", "a readable file");
  }
  bool next_line(std::string& text) {
    if (!std::getline(in, text)) return false;
    ++line;
    return true;
  }
  double next(const char* what) {
    std::string token;
    while (!(line_stream >> token)) {
      std::string text;
      if (!next_line(text)) throw DataError(path, line, "end of file", std::string(what) + " (file truncated?)");
      line_stream.clear();
      line_stream.str(text);
    }
    char* end = nullptr;
    const double value = std::strtod(token.c_str(), &end);
    if (end == token.c_str() || *end != '\0')
      throw DataError(path, line, "'" + token + "'", std::string("a number for ") + what);
    if (!std::isfinite(value)) throw DataError(path, line, "'" + token + "'", std::string("a finite number for ") + what);
    return value;
  }
};

}  // namespace

HullMesh read_gdf(const std::string& path) {
  NumberReader reader(path);
  std::string header;
  if (!reader.next_line(header)) throw DataError(path, 1, "an empty file", "a header line");
  const double ulen = reader.next("ULEN");
  reader.next("GRAV");
  const int ulen_line = reader.line;
  if (!(ulen > 0.0)) throw DataError(path, ulen_line, "ULEN = " + std::to_string(ulen), "ULEN > 0");
  const double isx = reader.next("ISX"), isy = reader.next("ISY");
  const int symmetry_line = reader.line;
  if ((isx != 0.0 && isx != 1.0) || (isy != 0.0 && isy != 1.0))
    throw DataError(path, symmetry_line, "ISX = " + std::to_string(isx) + ", ISY = " + std::to_string(isy),
                    "symmetry flags 0 or 1");
  const double npan = reader.next("NPAN");
  if (!(npan >= 1.0) || npan != std::floor(npan))
    throw DataError(path, reader.line, "NPAN = " + std::to_string(npan), "a positive panel count");
  HullMesh mesh;
  mesh.panels.reserve(static_cast<size_t>(npan));
  for (int p = 0; p < static_cast<int>(npan); ++p) {
    std::array<Vector3, 4> v;
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 3; ++c) v[k][c] = ulen * reader.next("a panel vertex coordinate");
    // Drop repeated vertices: a quadrilateral with two equal vertices is a triangle.
    HullPanel panel;
    panel.num_vertices = 0;
    for (int k = 0; k < 4; ++k)
      if (panel.num_vertices == 0 || v[k] != panel.vertices[panel.num_vertices - 1])
        panel.vertices[panel.num_vertices++] = v[k];
    if (panel.num_vertices > 1 && panel.vertices[panel.num_vertices - 1] == panel.vertices[0]) --panel.num_vertices;
    if (panel.num_vertices < 3)
      throw DataError(path, reader.line, "panel " + std::to_string(p + 1) + " with fewer than 3 distinct vertices",
                      "a triangle or quadrilateral");
    mesh.panels.push_back(panel);
  }
  if (isx == 1.0) mesh.append(mirrored(mesh, 0));
  if (isy == 1.0) mesh.append(mirrored(mesh, 1));
  return mesh;
}

HullMesh read_stl(const std::string& path) {
  require_readable_data_file(path, "STL hull mesh");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DataError(path, 0, "a file that cannot be opened", "a readable STL file");
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  HullMesh mesh;
  // Binary STL: 80-byte header, uint32 count, 50 bytes per triangle. Some binary
  // files begin with "solid" too, so decide by the size.
  if (content.size() >= 84) {
    std::uint32_t count;
    std::memcpy(&count, content.data() + 80, 4);
    if (content.size() == 84 + 50ull * count) {
      for (std::uint32_t t = 0; t < count; ++t) {
        HullPanel panel;
        panel.num_vertices = 3;
        for (int k = 0; k < 3; ++k)
          for (int c = 0; c < 3; ++c) {
            float value;
            std::memcpy(&value, content.data() + 84 + 50ull * t + 12 + 12 * k + 4 * c, 4);
            panel.vertices[k][c] = value;
          }
        mesh.panels.push_back(panel);
      }
      return mesh;
    }
  }
  std::istringstream text(content);
  std::string line_text;
  int line = 0, k = 0;
  HullPanel panel;
  panel.num_vertices = 3;
  while (std::getline(text, line_text)) {
    ++line;
    std::istringstream words(line_text);
    std::string word;
    if (!(words >> word) || word != "vertex") continue;
    Vector3& v = panel.vertices[k];
    if (!(words >> v.x() >> v.y() >> v.z()) || !v.allFinite())
      throw DataError(path, line, "'" + line_text + "'", "'vertex x y z' with three finite numbers");
    if (++k == 3) {
      mesh.panels.push_back(panel);
      k = 0;
    }
  }
  if (mesh.panels.empty() || k != 0)
    throw DataError(path, line, "no complete triangle", "an ASCII or binary STL file with facets");
  return mesh;
}

}  // namespace heavesim::hydro
