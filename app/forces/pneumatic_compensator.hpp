#pragma once
// Force kind `pneumatic_compensator`: a passive gas-spring compensator on a stroke
// (control/pneumatic/pneumatic_compensator.hpp; docs/case-format.md, "Compensators").
#include "app/forces/compensator_stroke.hpp"
#include "control/pneumatic/pneumatic_compensator.hpp"

namespace heavesim {

struct PneumaticCompensatorDefinition {
  static constexpr std::string_view type = "pneumatic_compensator";
  static constexpr BuildStage stage = BuildStage::compensators;
  static std::span<const KeySpec> keys();
  static std::span<const SchemaSection> sub_sections();
  /// Checks every parameter that can be checked without the model.
  static PneumaticCompensatorDefinition read(const NodeReader& item, const CaseDefinition& definition);
  /// Resolves the stroke on the assembled initial state, checks that it starts between
  /// the end stops, sets the gas pressure from the static balance where asked.
  void build(const std::string& name, SceneBuildContext& context) const;

  StrokeDefinition stroke;
  PneumaticParameters parameters;
  /// gas_pressure: balance -> parameters.gas_pressure is set from the static balance
  /// at the initial state (control/analysis/static_balance.hpp).
  bool balance_pressure = true;
};

}  // namespace heavesim
