#include "app/forces/point_force.hpp"

#include "app/scene/scene_build_context.hpp"
#include "kernel/elements/point_force.hpp"

namespace heavesim {
namespace {

constexpr KeySpec point_force_keys[] = {
    {"name", "text", "–", "required", "unique"},
    {"type", "choice", "–", "required", "point_force"},
    {"body", "text", "–", "required", "the loaded body"},
    {"point", "vector", "m", "`[0, 0, 0]`", "the loaded point, body frame"},
    {"force", "vector", "N", "required", "constant force, world frame"},
    {"description", "text", "–", "–", "free text"},
};

}  // namespace

std::span<const KeySpec> PointForceDefinition::keys() { return point_force_keys; }

PointForceDefinition PointForceDefinition::read(const NodeReader& item, const CaseDefinition&) {
  PointForceDefinition def;
  item.expect_section(type);
  def.body = item["body"].text();
  def.force_world = item["force"].vector3();
  if (auto point = item.optional("point")) def.point = point->vector3_in(length_range);
  return def;
}

void PointForceDefinition::build(const std::string& name, SceneBuildContext& context) const {
  context.system.add_force_element(
      std::make_unique<PointForce>(name, context.body_point(name, "body", body, point), force_world));
}

}  // namespace heavesim
