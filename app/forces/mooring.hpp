#pragma once
// Force kind `mooring`: a linear mooring of a body, f = f0 - K x (hydro::LinearRestoring).

#include "app/forces/hydro_force.hpp"

namespace heavesim {

struct MooringDefinition {
  static constexpr std::string_view type = "mooring";
  static constexpr BuildStage stage = BuildStage::hydro;
  static std::span<const KeySpec> keys();
  static std::span<const SchemaSection> sub_sections() { return {}; }
  static MooringDefinition read(const NodeReader& item, const CaseDefinition& definition);
  void build(const std::string& name, SceneBuildContext& context) const;

  std::string body;
  hydro::Matrix6 stiffness = hydro::Matrix6::Zero();   // K [N/m, N, N m/rad], reference point, WAMIT order
  hydro::Vector6 pretension = hydro::Vector6::Zero();  // f0 [N, N m]
};

}  // namespace heavesim
