#include "app/scene/hydro_scene.hpp"

#include <cmath>
#include <memory>
#include <set>

#include <fmt/format.h>

#include "io/bem/bem_file.hpp"
#include "app/scene/recorded_load.hpp"
#include "hydro/elements/element_factories.hpp"
#include "hydro/elements/nonlinear_hydrostatics.hpp"
#include "hydro/elements/wave_excitation.hpp"
#include "hydro/excitation/semisubmersible_heave.hpp"
#include "hydro/radiation/added_mass.hpp"
#include "hydro/waves/wave_spectrum.hpp"

namespace heavesim {
namespace {

InputError hydro_error(const CaseDefinition& definition, const std::string& name, const std::string& field,
                       const std::string& found, const std::string& expected) {
  return definition.item_error(name, field, found, expected);
}

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

/// Reads one data file; a DataError points at the case key and names the data file's line
/// (or, for an HDF5 file, its dataset: the DataError's file is then "<path>:<dataset>").
template <class Read>
auto read_checked(const CaseDefinition& definition, const HydroForceDefinition& force, Read read) {
  try {
    return read();
  } catch (const hydro::DataError& error) {
    const std::string where = error.line() > 0 ? fmt::format("{}:{}", error.file(), error.line()) : error.file();
    throw hydro_error(definition, force.name, force.file_key, error.found() + " (in " + where + ")",
                      error.expected());
  }
}

bem::WamitScaling scaling(const CaseDefinition& definition, const HydroForceDefinition& force) {
  return {definition.water.density, definition.gravity.norm(), force.length_scale};
}

const BodyDefinition* find_body(const CaseDefinition& definition, const std::string& body) {
  for (const BodyDefinition& b : definition.bodies)
    if (b.name == body) return &b;
  return nullptr;
}

}  // namespace

HydroData read_hydro_data(const CaseDefinition& definition) {
  HydroData data;
  data.waves = std::make_shared<const hydro::WaveTrain>(wave_train(definition));
  std::set<std::string> radiating_bodies;
  auto add_inertia = [&](const std::string& body, const Matrix6& added) {
    data.added_inertia.try_emplace(body, Matrix6::Zero()).first->second += added;  // several elements add up
  };
  for (const HydroForceDefinition& force : definition.hydro_forces) {
    const bem::WamitScaling s = scaling(definition, force);
    using Type = HydroForceDefinition::Type;
    if (force.type == Type::added_mass) {
      add_inertia(force.body, hydro::added_inertia_in_body_frame(force.added_mass));
    } else if (force.type == Type::radiation) {
      if (!radiating_bodies.insert(force.body).second)
        throw hydro_error(definition, force.name, "body", "a second radiation element on '" + force.body + "'",
                          "one radiation element per body (its A(inf) is the body's added inertia)");
      const auto& radiation = data.radiation[force.name] =
          read_checked(definition, force, [&] { return bem::read_radiation_file(force.file, s); });
      add_inertia(force.body, hydro::added_inertia_in_body_frame(radiation.added_mass_infinite));
    } else if (force.type == Type::wave_excitation && force.heave_estimate) {
      // Evaluated at the sea's own component frequencies: exact, no interpolation.
      std::vector<double> frequencies;
      for (const hydro::WaveComponent& c : data.waves->components()) frequencies.push_back(c.angular_frequency);
      data.excitation[force.name] = hydro::semisubmersible_heave_excitation_table(
          *force.heave_estimate, frequencies, definition.water.density, definition.gravity.norm());
    } else if (force.type == Type::wave_excitation) {
      data.excitation[force.name] = read_checked(definition, force, [&] { return bem::read_excitation_file(force.file, s); });
    } else if (force.type == Type::hydrostatics && force.file.empty()) {
      data.stiffness[force.name] = force.stiffness;
    } else if (force.type == Type::hydrostatics && !force.nonlinear) {
      data.stiffness[force.name] = read_checked(definition, force, [&] { return bem::read_hydrostatic_stiffness_file(force.file, s); });
    } else if (force.type == Type::hydrostatics) {
      const bool stl = force.file.size() > 4 && (force.file.substr(force.file.size() - 4) == ".stl" ||
                                                 force.file.substr(force.file.size() - 4) == ".STL");
      data.meshes[force.name] =
          read_checked(definition, force, [&] { return stl ? hydro::read_stl(force.file) : hydro::read_gdf(force.file); });
    }
  }
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

void add_hydro_elements(const CaseDefinition& definition, const HydroData& data, const Model& model,
                        MultibodySystem& system) {
  if (definition.hydro_forces.empty()) return;
  const std::shared_ptr<const hydro::WaveTrain>& waves = data.waves;
  const double g = definition.gravity.norm(), rho = definition.water.density;
  using Type = HydroForceDefinition::Type;
  for (const HydroForceDefinition& force : definition.hydro_forces) {
    const int link = model.link_index(force.body);
    if (force.body == ModelBuilder::ground_name || link < 0)
      throw hydro_error(definition, force.name, "body", "'" + force.body + "', which is not a body",
                        "the name of a floating body");
    std::unique_ptr<ForceElement> element;
    std::shared_ptr<const hydro::WaveTrain> recorded_waves;
    try {
      switch (force.type) {
        case Type::hydrostatics:
          if (force.nonlinear) {
            element =
                std::make_unique<hydro::NonlinearHydrostatics>(force.name, link, data.meshes.at(force.name), rho, g);
          } else {
            const BodyDefinition& body = *find_body(definition, force.body);  // the model has it
            hydro::LinearHydrostaticsSettings settings;
            settings.stiffness = data.stiffness.at(force.name);
            settings.stiffness_includes_gravity = force.hst_includes_gravity;
            settings.displaced_volume = force.displaced_volume;
            settings.body_mass = body.inertia.mass();
            settings.center_of_mass = body.inertia.com();
            settings.water_density = rho;
            settings.gravity = g;
            element = hydro::linear_hydrostatics(force.name, link, settings);
          }
          break;
        case Type::radiation:
          element = hydro::radiation_memory(force.name, link, data.radiation.at(force.name), force.memory);
          break;
        case Type::wave_excitation:
          element = std::make_unique<hydro::WaveExcitation>(force.name, link, data.excitation.at(force.name), *waves);
          recorded_waves = waves;
          break;
        case Type::linear_damping:
          element = std::make_unique<hydro::BodyDamping>(force.name, link, force.damping);
          break;
        case Type::quadratic_damping:
          element = std::make_unique<hydro::BodyDamping>(force.name, link, hydro::Matrix6::Zero(),
                                                         force.quadratic_coefficients);
          break;
        case Type::added_mass:
          continue;  // in the body's inertia (read_hydro_data)
        case Type::mooring:
          element = std::make_unique<hydro::LinearRestoring>(force.name, link, force.stiffness, force.pretension,
                                                             Transform::Identity());
          break;
      }
    } catch (const ParameterError& error) {
      throw to_input_error(definition, definition.item_paths.at(force.name), error);
    }
    system.add_force_element(std::make_unique<RecordedLoad>(std::move(element), model, link, recorded_waves));
  }
}

}  // namespace heavesim
