#include "app/scene/hydro_scene.hpp"

#include <memory>

#include "hydro/waves/wave_spectrum.hpp"

namespace heavesim {
namespace {

/// The case key of each parameter of hydro's sea (WaveTrain, spectra, dispersion).
const std::map<std::string, std::string>& sea_keys() {
  static const std::map<std::string, std::string> keys{
      {"significant_height", "waves.hs"},  {"peak_period", "waves.tp"},
      {"peak_enhancement", "waves.gamma"}, {"num_components", "waves.components"},
      {"min_frequency", "waves.min_frequency"}, {"max_frequency", "waves.max_frequency"},
      {"height", "waves.amplitude"},       {"period", "waves.period"},
      {"angular_frequency", "waves.period"}, {"gravity", "environment.gravity"},
      {"depth", "environment.water_depth"}};
  return keys;
}

}  // namespace

HydroData read_hydro_data(const CaseDefinition& definition) {
  HydroData data;
  data.waves = std::make_shared<const hydro::WaveTrain>(wave_train(definition));
  for (const ForceDefinition& force : definition.forces)
    std::visit(
        [&](const auto& kind) {
          if constexpr (requires { kind.read_data(force.name, definition, data); })
            kind.read_data(force.name, definition, data);
        },
        force.kind);
  return data;
}

namespace {

hydro::WaveTrain unchecked_wave_train(const CaseDefinition& definition) {
  const WaveDefinition& waves = definition.waves;
  const double g = definition.gravity.norm();
  if (waves.type == WaveDefinition::Type::regular)
    return hydro::regular_wave(2.0 * waves.amplitude, waves.period, waves.heading, waves.phase, definition.water.depth,
                               waves.ramp, g);
  if (!waves.declared()) return {};
  hydro::IrregularSeaSettings settings = waves.irregular;
  settings.heading = waves.heading;
  settings.depth = definition.water.depth;
  settings.gravity = g;
  settings.ramp = waves.ramp;
  if (waves.type == WaveDefinition::Type::jonswap)
    return hydro::irregular_sea(hydro::Jonswap(waves.significant_height, waves.peak_period, waves.peak_enhancement),
                                settings);
  hydro::check_sea_state(waves.significant_height, waves.peak_period);
  return hydro::irregular_sea(hydro::PiersonMoskowitz{waves.significant_height, waves.peak_period}, settings);
}

}  // namespace

hydro::WaveTrain wave_train(const CaseDefinition& definition) {
  try {
    return unchecked_wave_train(definition);
  } catch (const ParameterError& error) {
    throw to_input_error(definition, "", error, sea_keys());
  }
}

}  // namespace heavesim
