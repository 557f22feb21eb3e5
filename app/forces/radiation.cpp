#include "app/forces/radiation.hpp"

#include <algorithm>
#include <climits>

#include <fmt/format.h>

#include "app/scene/hydro_scene.hpp"
#include "app/scene/scene_build_context.hpp"
#include "hydro/radiation/added_mass.hpp"

namespace heavesim {
namespace {

constexpr KeySpec radiation_keys[] = {
    {"name", "text", "–", "required", "unique"},
    {"type", "choice", "–", "required", "radiation"},
    {"body", "text", "–", "required", "the floating body"},
    {"file", "text", "–", "required", "WAMIT .1, BEMIO .h5 or Capytaine .nc file"},
    {"memory", "choice", "–", "`state_space`", "state_space or convolution"},
    {"state_space_order", "number", "–", "12", "states per realised mode pair, 2 .. 24"},
    {"kernel_duration", "number", "s", "60", "length of K(t)"},
    {"kernel_step", "number", "s", "0.05", "sample step of K(t)"},
    {"modes", "list", "–", "all", "WAMIT modes 1..6 whose memory is kept"},
    {"length_scale", "number", "m", "1", "WAMIT ULEN"},
    {"description", "text", "–", "–", "free text"},
};

}  // namespace

std::span<const KeySpec> RadiationDefinition::keys() { return radiation_keys; }

RadiationDefinition RadiationDefinition::read(const NodeReader& item, const CaseDefinition&) {
  RadiationDefinition def;
  item.expect_section("radiation");
  hydro::RadiationMemorySettings& memory = def.memory;
  if (auto kind = item.optional("memory"))
    memory.convolution = kind->choice({"state_space", "convolution"}) == "convolution";
  // The order's range and the kernel's sampling are hydro's rules (state_space.hpp,
  // retardation_kernel.hpp), checked when the scene builds the element.
  if (auto order = item.optional("state_space_order"))
    memory.state_space_order = static_cast<int>(std::clamp<long>(order->integer(), INT_MIN, INT_MAX));
  if (auto duration = item.optional("kernel_duration")) memory.kernel_duration = duration->positive_number();
  if (auto step = item.optional("kernel_step")) memory.kernel_step = step->positive_number();
  if (auto modes = item.optional("modes")) {
    memory.modes.fill(false);
    for (const NodeReader& mode : modes->items()) {
      const long m = mode.integer();
      if (m < 1 || m > 6) mode.fail(fmt::format("{}", m), "a WAMIT mode 1..6 (surge, sway, heave, roll, pitch, yaw)");
      memory.modes[m - 1] = true;
    }
  }
  def.body = item["body"].text();
  def.file = read_data_file(item, "file", false);
  return def;
}

void RadiationDefinition::read_data(const std::string& name, const CaseDefinition& definition, HydroData& data) const {
  if (!data.radiating_bodies.insert(body).second)
    throw definition.item_error(name, "body", "a second radiation element on '" + body + "'",
                                "one radiation element per body (its A(inf) is the body's added inertia)");
  const auto& radiation = data.radiation[name] = read_checked(definition, name, file, [&] {
    return bem::read_radiation_file(file.path, wamit_scaling(definition, file.length_scale));
  });
  data.add_inertia(body, hydro::added_inertia_in_body_frame(radiation.added_mass_infinite));
}

void RadiationDefinition::build(const std::string& name, SceneBuildContext& context) const {
  add_hydro_element(context, name, body, [&](int link) {
    return hydro::radiation_memory(name, link, context.hydro_data.radiation.at(name), memory);
  });
}

}  // namespace heavesim
