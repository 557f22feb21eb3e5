#pragma once
// Force kind `linear_damping`: linear viscous damping of a body, -B v (hydro::BodyDamping).

#include "app/forces/hydro_force.hpp"

namespace heavesim {

struct LinearDampingDefinition {
  static constexpr std::string_view type = "linear_damping";
  static constexpr BuildStage stage = BuildStage::hydro;
  static std::span<const KeySpec> keys();
  static std::span<const SchemaSection> sub_sections() { return {}; }
  static LinearDampingDefinition read(const NodeReader& item, const CaseDefinition& definition);
  void build(const std::string& name, SceneBuildContext& context) const;

  std::string body;
  hydro::Matrix6 damping = hydro::Matrix6::Zero();  // B [N s/m, N s, N m s/rad], reference point, WAMIT order
};

}  // namespace heavesim
