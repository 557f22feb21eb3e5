#pragma once
// Force kind `active_compensator`: a controlled actuator (a force actuator or a
// valve-controlled hydraulic cylinder) on a stroke (control/active/active_compensator.hpp;
// docs/case-format.md, "Compensators").
#include <optional>

#include "app/forces/compensator_stroke.hpp"
#include "control/active/active_compensator.hpp"

namespace heavesim {

struct ActiveCompensatorDefinition {
  static constexpr std::string_view type = "active_compensator";
  static constexpr BuildStage stage = BuildStage::compensators;
  static std::span<const KeySpec> keys();
  static std::span<const SchemaSection> sub_sections();
  /// Checks every parameter that can be checked without the model.
  static ActiveCompensatorDefinition read(const NodeReader& item, const CaseDefinition& definition);
  /// Resolves the stroke and the controlled point on the assembled initial state, takes
  /// the initial references; once every compensator is built, checks the closed loop
  /// on its stroke is stable (control/analysis/stroke_loop.hpp).
  void build(const std::string& name, SceneBuildContext& context) const;

  StrokeDefinition stroke;
  /// The initial references (controlled and base heights, initial stroke) and the
  /// controlled point are set by build.
  ActiveCompensatorParameters parameters;
  std::optional<std::string> controlled_body;  // default: the moving side of the stroke
  Vector3 controlled_point = Vector3::Zero();  // m, that body's frame
};

}  // namespace heavesim
