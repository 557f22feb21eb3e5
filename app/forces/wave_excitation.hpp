#pragma once
// Force kind `wave_excitation`: the first-order wave excitation of a body from a WAMIT .3,
// BEMIO .h5 or Capytaine .nc file, or from the semi-submersible hand estimate
// (hydro/excitation/semisubmersible_heave.hpp), in the case's sea.
#include <optional>

#include "app/forces/hydro_force.hpp"
#include "hydro/excitation/semisubmersible_heave.hpp"

namespace heavesim {

struct WaveExcitationDefinition {
  static constexpr std::string_view type = "wave_excitation";
  static constexpr BuildStage stage = BuildStage::hydro;
  static std::span<const KeySpec> keys();
  static std::span<const SchemaSection> sub_sections();
  static WaveExcitationDefinition read(const NodeReader& item, const CaseDefinition& definition);
  /// Reads the file, or evaluates the estimate at the sea's component frequencies.
  void read_data(const std::string& name, const CaseDefinition& definition, HydroData& data) const;
  void build(const std::string& name, SceneBuildContext& context) const;

  std::string body;
  HydroDataFile file;  // the .3 / .h5 / .nc file; no file with a heave estimate
  /// The semi-submersible hand estimate instead of a file.
  std::optional<hydro::SemisubmersibleHeaveEstimate> heave_estimate;
};

}  // namespace heavesim
