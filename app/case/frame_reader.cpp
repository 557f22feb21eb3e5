// Reads orientations and frames (docs/case-format.md, "Orientations" and "frame").
#include "app/case/frame_reader.hpp"

#include <cmath>

#include <fmt/format.h>

#include "kernel/spatial/rotation.hpp"

namespace heavesim {

/// orientation: {axis: [..], angle: ..} | {rpy: [roll, pitch, yaw]} | {quaternion: [w, x, y, z]}
///              | {matrix: [[..], [..], [..]]}; R maps the frame's axes to its parent's.
Matrix3 read_orientation(const NodeReader& reader) {
  reader.expect_section("orientation");
  const int forms = reader.has("axis") + reader.has("rpy") + reader.has("quaternion") + reader.has("matrix");
  if (forms != 1)
    reader.fail("exactly one of {axis, angle}, {rpy}, {quaternion}, {matrix}");
  if (reader.has("axis")) {
    if (!reader.has("angle")) reader.fail("'angle' next to 'axis'");
    return axis_angle_rotation(reader["axis"].unit_vector3(), reader["angle"].number());
  }
  if (reader.has("angle")) reader.fail("'angle' only together with 'axis'");
  if (reader.has("rpy")) {
    const Vector3 rpy = reader["rpy"].vector3();
    return (Eigen::AngleAxisd(rpy.z(), Vector3::UnitZ()) * Eigen::AngleAxisd(rpy.y(), Vector3::UnitY()) *
            Eigen::AngleAxisd(rpy.x(), Vector3::UnitX()))
        .toRotationMatrix();
  }
  if (reader.has("quaternion")) {
    const NodeReader q = reader["quaternion"];
    const std::vector<double> values = q.numbers();
    if (values.size() != 4) q.fail("a unit quaternion [w, x, y, z]");
    const Eigen::Quaterniond quaternion(values[0], values[1], values[2], values[3]);
    if (std::abs(quaternion.norm() - 1.0) > 1e-6)
      q.fail(fmt::format("{} with norm {:.6g}", q.node().describe(), quaternion.norm()), "a unit quaternion [w, x, y, z]");
    return quaternion.normalized().toRotationMatrix();
  }
  const NodeReader matrix_reader = reader["matrix"];
  const std::vector<NodeReader> rows = matrix_reader.items();
  if (rows.size() != 3) matrix_reader.fail("3 rows of 3 numbers");
  Matrix3 R;
  for (int r = 0; r < 3; ++r) R.row(r) = rows[r].vector3().transpose();
  if (!(R.transpose() * R).isApprox(Matrix3::Identity(), 1e-6) || R.determinant() < 0.0)
    matrix_reader.fail("a matrix that is not a proper rotation", "an orthonormal matrix with determinant +1");
  return R;
}

/// frame: {position: [x, y, z], orientation: {...}}; identity when absent.
Transform read_frame(const std::optional<NodeReader>& reader) {
  if (!reader) return Transform::Identity();
  reader->expect_section("frame");
  Transform frame;
  if (auto position = reader->optional("position")) frame.translation() = position->vector3_in(length_range);
  if (auto orientation = reader->optional("orientation")) frame.rotation() = read_orientation(*orientation);
  return frame;
}

}  // namespace heavesim
