#pragma once
// Orientations and frames of a case (docs/case-format.md, "Orientations"): read by the
// joints (parent_frame, child_frame, initial, spring rest) and the angle drivers
// (frame_a, frame_b).
#include <optional>

#include "app/case/node_reader.hpp"
#include "kernel/spatial/transform.hpp"

namespace heavesim {

/// orientation: {axis: [..], angle: ..} | {rpy: [roll, pitch, yaw]} | {quaternion: [w, x, y, z]}
///              | {matrix: [[..], [..], [..]]}; R maps the frame's axes to its parent's.
Matrix3 read_orientation(const NodeReader& reader);

/// frame: {position: [x, y, z] (m), orientation: {...}}: a frame in its body's frame;
/// identity when absent.
Transform read_frame(const std::optional<NodeReader>& reader);

}  // namespace heavesim
