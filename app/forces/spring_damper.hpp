#pragma once
// Force kind `spring_damper`: a linear spring-damper between two body points
// (kernel/elements/spring_damper.hpp).
#include "app/forces/force_kind.hpp"
#include "kernel/elements/spring_damper.hpp"

namespace heavesim {

struct SpringDamperDefinition {
  static constexpr std::string_view type = "spring_damper";
  static constexpr BuildStage stage = BuildStage::on_model;
  static std::span<const KeySpec> keys();
  static std::span<const SchemaSection> sub_sections() { return {}; }
  static SpringDamperDefinition read(const NodeReader& item, const CaseDefinition& definition);
  void build(const std::string& name, SceneBuildContext& context) const;

  std::string body_a, body_b;         // the ends' bodies ("ground" for the world)
  Vector3 point_a = Vector3::Zero();  // m, body a's frame
  Vector3 point_b = Vector3::Zero();  // m, body b's frame
  SpringDamperParameters spring;      // k [N/m], c [N s/m], l0 [m]
};

}  // namespace heavesim
