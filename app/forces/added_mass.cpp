#include "app/forces/added_mass.hpp"

#include "app/scene/hydro_scene.hpp"
#include "app/scene/scene_build_context.hpp"
#include "hydro/radiation/added_mass.hpp"

namespace heavesim {
namespace {

constexpr KeySpec added_mass_keys[] = {
    {"name", "text", "–", "required", "unique"},
    {"type", "choice", "–", "required", "added_mass"},
    {"body", "text", "–", "required", "the floating body"},
    {"matrix", "matrix", "kg, kg m, kg m²", "required", "A, 6 x 6 or its diagonal"},
    {"description", "text", "–", "–", "free text"},
};

}  // namespace

std::span<const KeySpec> AddedMassDefinition::keys() { return added_mass_keys; }

AddedMassDefinition AddedMassDefinition::read(const NodeReader& item, const CaseDefinition&) {
  AddedMassDefinition def;
  // Constant added mass (e.g. the fallback A of docs/physics/drilling-rig.md §4) put into the
  // body's inertia like a radiation element's A(inf); no force of its own.
  item.expect_section("added_mass");
  def.added_mass = read_matrix6(item["matrix"]);
  check_symmetric_positive(item["matrix"], def.added_mass, "mass");
  def.body = item["body"].text();
  return def;
}

void AddedMassDefinition::read_data(const std::string&, const CaseDefinition&, HydroData& data) const {
  data.add_inertia(body, hydro::added_inertia_in_body_frame(added_mass));
}

void AddedMassDefinition::build(const std::string& name, SceneBuildContext& context) const {
  // In the body's inertia (read_data); only the body is checked here.
  floating_body_link(context, name, body);
}

}  // namespace heavesim
