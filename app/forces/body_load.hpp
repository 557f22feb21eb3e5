#pragma once
// Force kind `body_load`: a force [N] at a body point and a couple [N m] on the body,
// each component an expression of time t [s] (a muParser expression, parsed as a
// driver's `position` is: app/case/time_function.hpp), given either in the body frame
// (`frame: body`, default: a follower load that turns with the body, such as a thruster
// or a jack fixed on it) or in the world frame (`frame: world`: fixed direction, such as
// a hook load or a wind load of fixed heading).
#include <array>
#include <memory>

#include "app/case/time_function.hpp"
#include "app/forces/force_kind.hpp"
#include "kernel/spatial/types.hpp"

namespace heavesim {

struct BodyLoadDefinition {
  static constexpr std::string_view type = "body_load";
  static constexpr BuildStage stage = BuildStage::on_model;
  static std::span<const KeySpec> keys();
  static std::span<const SchemaSection> sub_sections() { return {}; }
  static BodyLoadDefinition read(const NodeReader& item, const CaseDefinition& definition);
  void build(const std::string& name, SceneBuildContext& context) const;

  using Components = std::array<std::shared_ptr<const TimeFunction>, 3>;  // null: 0
  std::string body;                 // the loaded body
  Vector3 point = Vector3::Zero();  // m, body frame: where the force acts
  bool world_frame = false;         // frame: world (else the body frame)
  Components force;                 // N, components in `frame`
  Components moment;                // N m, components in `frame`
};

}  // namespace heavesim
