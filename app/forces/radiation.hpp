#pragma once
// Force kind `radiation`: the radiation memory of a body from a WAMIT .1, BEMIO .h5 or
// Capytaine .nc file (state space or convolution, hydro/elements/element_factories.hpp);
// its A(inf) is the body's added inertia.

#include "app/forces/hydro_force.hpp"

namespace heavesim {

struct RadiationDefinition {
  static constexpr std::string_view type = "radiation";
  static constexpr BuildStage stage = BuildStage::hydro;
  static std::span<const KeySpec> keys();
  static std::span<const SchemaSection> sub_sections() { return {}; }
  static RadiationDefinition read(const NodeReader& item, const CaseDefinition& definition);
  /// Reads the file; adds A(inf) to the body's added inertia (one radiation element per body).
  void read_data(const std::string& name, const CaseDefinition& definition, HydroData& data) const;
  void build(const std::string& name, SceneBuildContext& context) const;

  std::string body;
  HydroDataFile file;                    // the .1 / .h5 / .nc file
  hydro::RadiationMemorySettings memory;  // state space or convolution, kernel sampling, modes
};

}  // namespace heavesim
