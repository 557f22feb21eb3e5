#include "app/forces/linear_damping.hpp"

#include "app/scene/scene_build_context.hpp"

namespace heavesim {
namespace {

constexpr KeySpec linear_damping_keys[] = {
    {"name", "text", "–", "required", "unique"},
    {"type", "choice", "–", "required", "linear_damping"},
    {"body", "text", "–", "required", "the floating body"},
    {"damping", "matrix", "N s/m, N s, N m s/rad", "required", "B, 6 x 6 or its diagonal"},
    {"description", "text", "–", "–", "free text"},
};

}  // namespace

std::span<const KeySpec> LinearDampingDefinition::keys() { return linear_damping_keys; }

LinearDampingDefinition LinearDampingDefinition::read(const NodeReader& item, const CaseDefinition&) {
  LinearDampingDefinition def;
  item.expect_section("linear_damping");
  def.damping = read_matrix6(item["damping"]);
  check_symmetric_positive(item["damping"], def.damping, "damping");
  def.body = item["body"].text();
  return def;
}

void LinearDampingDefinition::build(const std::string& name, SceneBuildContext& context) const {
  add_hydro_element(context, name, body, [&](int link) { return std::make_unique<hydro::BodyDamping>(name, link, damping); });
}

}  // namespace heavesim
