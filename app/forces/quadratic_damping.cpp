#include "app/forces/quadratic_damping.hpp"

#include "app/scene/scene_build_context.hpp"

namespace heavesim {
namespace {

constexpr KeySpec quadratic_damping_keys[] = {
    {"name", "text", "–", "required", "unique"},
    {"type", "choice", "–", "required", "quadratic_damping"},
    {"body", "text", "–", "required", "the floating body"},
    {"coefficients", "vector", "N s²/m², N m s²/rad²", "required", "b_i >= 0"},
    {"description", "text", "–", "–", "free text"},
};

}  // namespace

std::span<const KeySpec> QuadraticDampingDefinition::keys() { return quadratic_damping_keys; }

QuadraticDampingDefinition QuadraticDampingDefinition::read(const NodeReader& item, const CaseDefinition&) {
  QuadraticDampingDefinition def;
  item.expect_section("quadratic_damping");
  def.coefficients = read_vector6(item["coefficients"]);
  if ((def.coefficients.array() < 0.0).any()) item["coefficients"].fail("a negative coefficient", "coefficients >= 0");
  def.body = item["body"].text();
  return def;
}

void QuadraticDampingDefinition::build(const std::string& name, SceneBuildContext& context) const {
  add_hydro_element(context, name, body, [&](int link) {
    return std::make_unique<hydro::BodyDamping>(name, link, hydro::Matrix6::Zero(), coefficients);
  });
}

}  // namespace heavesim
