#pragma once
// Force kind `added_mass`: constant added mass (e.g. the fallback A of
// docs/physics/drilling-rig.md §4), put into the body's inertia like a radiation
// element's A(inf) (hydro/radiation/added_mass.hpp); no force of its own.

#include "app/forces/hydro_force.hpp"

namespace heavesim {

struct AddedMassDefinition {
  static constexpr std::string_view type = "added_mass";
  static constexpr BuildStage stage = BuildStage::hydro;
  static std::span<const KeySpec> keys();
  static std::span<const SchemaSection> sub_sections() { return {}; }
  static AddedMassDefinition read(const NodeReader& item, const CaseDefinition& definition);
  /// Adds A to the body's added inertia.
  void read_data(const std::string& name, const CaseDefinition& definition, HydroData& data) const;
  void build(const std::string& name, SceneBuildContext& context) const;

  std::string body;
  hydro::Matrix6 added_mass = hydro::Matrix6::Zero();  // A [kg, kg m, kg m^2], reference point, WAMIT order
};

}  // namespace heavesim
