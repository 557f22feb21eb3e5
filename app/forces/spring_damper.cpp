#include "app/forces/spring_damper.hpp"

#include "app/scene/scene_build_context.hpp"

namespace heavesim {
namespace {

constexpr KeySpec spring_damper_keys[] = {
    {"name", "text", "–", "required", "unique"},
    {"type", "choice", "–", "required", "spring_damper"},
    {"body_a", "text", "–", "required", "first end's body (or ground)"},
    {"point_a", "vector", "m", "`[0, 0, 0]`", "first end, body a's frame"},
    {"body_b", "text", "–", "required", "second end's body (or ground)"},
    {"point_b", "vector", "m", "`[0, 0, 0]`", "second end, body b's frame"},
    {"stiffness", "number", "N/m", "0", "k"},
    {"damping", "number", "N s/m", "0", "c"},
    {"rest_length", "number", "m", "required", "l0"},
    {"description", "text", "–", "–", "free text"},
};

}  // namespace

std::span<const KeySpec> SpringDamperDefinition::keys() { return spring_damper_keys; }

SpringDamperDefinition SpringDamperDefinition::read(const NodeReader& item, const CaseDefinition&) {
  SpringDamperDefinition def;
  item.expect_section(type);
  def.body_a = item["body_a"].text();
  def.body_b = item["body_b"].text();
  if (auto point = item.optional("point_b")) def.point_b = point->vector3_in(length_range);
  def.spring.stiffness = item.optional("stiffness") ? item["stiffness"].non_negative_number() : 0.0;
  def.spring.damping = item.optional("damping") ? item["damping"].non_negative_number() : 0.0;
  def.spring.rest_length = item["rest_length"].non_negative_number(length_range);
  if (auto point = item.optional("point_a")) def.point_a = point->vector3_in(length_range);
  return def;
}

void SpringDamperDefinition::build(const std::string& name, SceneBuildContext& context) const {
  const BodyPoint a = context.body_point(name, "body_a", body_a, point_a);
  const BodyPoint b = context.body_point(name, "body_b", body_b, point_b);
  if (a.link == b.link) throw context.error(name, "body_b", "both ends on '" + body_a + "'", "two different bodies");
  context.system.add_force_element(std::make_unique<SpringDamper>(name, a, b, spring));
}

}  // namespace heavesim
