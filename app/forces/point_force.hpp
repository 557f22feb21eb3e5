#pragma once
// Force kind `point_force`: a constant world-frame force at a body point
// (kernel/elements/point_force.hpp).
#include "app/forces/force_kind.hpp"
#include "kernel/spatial/types.hpp"

namespace heavesim {

struct PointForceDefinition {
  static constexpr std::string_view type = "point_force";
  static constexpr BuildStage stage = BuildStage::on_model;
  static std::span<const KeySpec> keys();
  static std::span<const SchemaSection> sub_sections() { return {}; }
  static PointForceDefinition read(const NodeReader& item, const CaseDefinition& definition);
  void build(const std::string& name, SceneBuildContext& context) const;

  std::string body;                       // the loaded body
  Vector3 point = Vector3::Zero();        // m, body frame
  Vector3 force_world = Vector3::Zero();  // N, world frame
};

}  // namespace heavesim
