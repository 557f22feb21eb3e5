#pragma once
// Force kind `ground_contact`: a unilateral spring-damper on an earth-fixed horizontal
// surface (the bit on the formation, docs/physics/drilling-rig.md §2;
// kernel/elements/ground_contact.hpp), preloaded at the initial state.
#include "app/forces/force_kind.hpp"
#include "kernel/spatial/types.hpp"

namespace heavesim {

struct GroundContactDefinition {
  static constexpr std::string_view type = "ground_contact";
  /// The surface is placed from the point's initial height, so the initial state must be
  /// assembled first; added before the compensators, whose balance pressure then counts
  /// the preload.
  static constexpr BuildStage stage = BuildStage::on_assembled;
  static std::span<const KeySpec> keys();
  static std::span<const SchemaSection> sub_sections() { return {}; }
  static GroundContactDefinition read(const NodeReader& item, const CaseDefinition& definition);
  void build(const std::string& name, SceneBuildContext& context) const;

  std::string body;                 // the body that touches the ground
  Vector3 point = Vector3::Zero();  // m, the contact point, body frame
  double stiffness = 0.0;           // k_f [N/m] > 0
  double damping = 0.0;             // c_f [N s/m]
  /// The contact force [N] at the initial state (the weight on bit WOB0): the surface
  /// sits preload / k_f below the point's initial height.
  double preload = 0.0;
};

}  // namespace heavesim
