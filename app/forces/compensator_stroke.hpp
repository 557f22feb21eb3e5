#pragma once
// What the two compensator kinds (pneumatic_compensator.hpp, active_compensator.hpp)
// share: where a compensator acts (its stroke), the readers of the sub-sections both
// accept, the resolution of the stroke on the model, and the record of the compensators
// on each stroke from which an active compensator's closed-loop stability is checked
// (control/analysis/stroke_loop.hpp) once every compensator is built.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "app/forces/force_kind.hpp"
#include "control/analysis/stroke_loop.hpp"
#include "control/pneumatic/pneumatic_compensator.hpp"
#include "control/stroke/stroke_axis.hpp"

namespace heavesim {

/// Where a compensator acts: a prismatic joint, or two body points and an axis.
struct StrokeDefinition {
  std::string joint;                       // joint form: a prismatic joint's name
  std::string base_body, moving_body;      // body form ("ground" allowed for the base)
  Vector3 base_point = Vector3::Zero();    // m, base body frame
  Vector3 moving_point = Vector3::Zero();  // m, moving body frame
  Vector3 axis = Vector3::UnitZ();         // unit, base body frame
  double mid_stroke = 0.0;                 // m: q, or the axial distance, at s = 0
  bool joint_form() const { return !joint.empty(); }
  /// Whether both act along the same stroke (same joint, or same two bodies).
  bool same_as(const StrokeDefinition& other) const;
};

// The key tables of the sections both compensators nest (docs/case-format.md).
std::span<const KeySpec> stroke_keys();
std::span<const KeySpec> body_point_keys();
std::span<const KeySpec> seal_friction_keys();

// Readers of the compensators' shared keys (InputError naming the key).
double positive_or(const NodeReader& item, const std::string& key, double default_value);
double non_negative_or(const NodeReader& item, const std::string& key, double default_value);
/// An absolute pressure [Pa] that may not be below the atmosphere.
double absolute_pressure(const NodeReader& node, double atmospheric, const std::string& what);
/// {body, point} -> body name and point [m].
std::pair<std::string, Vector3> read_body_point(const NodeReader& reader);
StrokeDefinition read_stroke(const NodeReader& reader);
SealFriction read_friction(const NodeReader& reader);

/// The stroke on the model; an InputError at forces[name].stroke.* for a joint or body
/// that is not one; ParameterError("joint") for a joint that is not prismatic.
StrokeAxis resolve_stroke(const SceneBuildContext& context, const std::string& name, const StrokeDefinition& stroke);

/// The case key (under the compensator's path) of each parameter control/ checks.
const std::map<std::string, std::string>& compensator_keys();

/// A built compensator, as the closed-loop analysis of a stroke sees it.
struct CompensatorOnStroke {
  const StrokeDefinition* stroke;
  StrokeElementFactory analysis_element;  // the compensator on the analysis model's stroke
};

}  // namespace heavesim
