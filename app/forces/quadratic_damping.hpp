#pragma once
// Force kind `quadratic_damping`: quadratic (drag) damping of a body, -b_i |v_i| v_i per
// mode (hydro::BodyDamping).

#include "app/forces/hydro_force.hpp"

namespace heavesim {

struct QuadraticDampingDefinition {
  static constexpr std::string_view type = "quadratic_damping";
  static constexpr BuildStage stage = BuildStage::hydro;
  static std::span<const KeySpec> keys();
  static std::span<const SchemaSection> sub_sections() { return {}; }
  static QuadraticDampingDefinition read(const NodeReader& item, const CaseDefinition& definition);
  void build(const std::string& name, SceneBuildContext& context) const;

  std::string body;
  hydro::Vector6 coefficients = hydro::Vector6::Zero();  // b_quad [N s^2/m^2, N m s^2/rad^2], WAMIT order
};

}  // namespace heavesim
