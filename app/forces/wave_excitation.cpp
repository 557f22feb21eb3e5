#include "app/forces/wave_excitation.hpp"

#include <fmt/format.h>

#include "app/scene/hydro_scene.hpp"
#include "app/scene/scene_build_context.hpp"
#include "hydro/elements/wave_excitation.hpp"

namespace heavesim {
namespace {

constexpr KeySpec wave_excitation_keys[] = {
    {"name", "text", "–", "required", "unique"},
    {"type", "choice", "–", "required", "wave_excitation"},
    {"body", "text", "–", "required", "the floating body"},
    {"file", "text", "–", "one of file, heave_estimate", "WAMIT .3, BEMIO .h5 or Capytaine .nc file"},
    {"heave_estimate", "map", "–", "one of file, heave_estimate", "semi-submersible hand estimate"},
    {"length_scale", "number", "m", "1", "WAMIT ULEN"},
    {"description", "text", "–", "–", "free text"},
};

constexpr KeySpec heave_estimate_keys[] = {
    {"pontoon_bottom_area", "number", "m²", "required", "A_pb"},
    {"waterplane_area", "number", "m²", "required", "A_wp ≤ A_pb"},
    {"keel_depth", "number", "m", "required", "d_keel"},
    {"pontoon_top_depth", "number", "m", "required", "d_top < d_keel"},
    {"added_mass", "number", "kg", "required", "A33"},
    {"added_mass_depth", "number", "m", "required", "d_a"},
};

}  // namespace

std::span<const KeySpec> WaveExcitationDefinition::keys() { return wave_excitation_keys; }

std::span<const SchemaSection> WaveExcitationDefinition::sub_sections() {
  static const SchemaSection sections[] = {
      {"heave_estimate", heave_estimate_keys},
  };
  return sections;
}

WaveExcitationDefinition WaveExcitationDefinition::read(const NodeReader& item, const CaseDefinition& definition) {
  WaveExcitationDefinition def;
  item.expect_section("wave_excitation");
  if (item.has("file") == item.has("heave_estimate"))
    item.fail("exactly one of 'file' (a WAMIT .3, BEMIO .h5 or Capytaine .nc file) and 'heave_estimate' (the semi-submersible hand estimate)");
  std::string file_key;
  if (auto estimate = item.optional("heave_estimate")) {
    estimate->expect_section("heave_estimate");
    hydro::SemisubmersibleHeaveEstimate e;
    e.pontoon_bottom_area = (*estimate)["pontoon_bottom_area"].positive_number();
    e.waterplane_area = (*estimate)["waterplane_area"].positive_number();
    e.keel_depth = (*estimate)["keel_depth"].positive_number();
    e.pontoon_top_depth = (*estimate)["pontoon_top_depth"].positive_number();
    e.added_mass = (*estimate)["added_mass"].non_negative_number();
    e.added_mass_depth = (*estimate)["added_mass_depth"].positive_number();
    if (!(e.pontoon_top_depth < e.keel_depth))
      (*estimate)["pontoon_top_depth"].fail(
          fmt::format("{:g} m, not above the keel at {:g} m", e.pontoon_top_depth, e.keel_depth),
          "pontoon_top_depth < keel_depth (both depths below the still-water level)");
    if (!(e.waterplane_area <= e.pontoon_bottom_area))
      (*estimate)["waterplane_area"].fail(
          fmt::format("{:g} m^2, more than the pontoon bottoms' {:g} m^2", e.waterplane_area, e.pontoon_bottom_area),
          "waterplane_area <= pontoon_bottom_area (the columns stand on the pontoons)");
    def.heave_estimate = e;
  } else {
    file_key = "file";
  }
  if (!definition.waves.declared())
    item["type"].fail("wave_excitation without a sea", "a top-level 'waves:' block (declared before use)");
  def.body = item["body"].text();
  def.file = read_data_file(item, file_key, false);
  return def;
}

void WaveExcitationDefinition::read_data(const std::string& name, const CaseDefinition& definition,
                                         HydroData& data) const {
  if (heave_estimate) {
    // Evaluated at the sea's own component frequencies: exact, no interpolation.
    std::vector<double> frequencies;
    for (const hydro::WaveComponent& c : data.waves->components()) frequencies.push_back(c.angular_frequency);
    data.excitation[name] = hydro::semisubmersible_heave_excitation_table(
        *heave_estimate, frequencies, definition.water.density, definition.gravity.norm());
  } else {
    data.excitation[name] = read_checked(definition, name, file, [&] {
      return bem::read_excitation_file(file.path, wamit_scaling(definition, file.length_scale));
    });
  }
}

void WaveExcitationDefinition::build(const std::string& name, SceneBuildContext& context) const {
  const std::shared_ptr<const hydro::WaveTrain>& waves = context.hydro_data.waves;
  add_hydro_element(
      context, name, body,
      [&](int link) { return std::make_unique<hydro::WaveExcitation>(name, link, context.hydro_data.excitation.at(name), *waves); },
      waves);
}

}  // namespace heavesim
