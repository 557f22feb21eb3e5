#include "app/forces/ground_contact.hpp"

#include "app/scene/scene_build_context.hpp"
#include "kernel/elements/ground_contact.hpp"

namespace heavesim {
namespace {

constexpr KeySpec ground_contact_keys[] = {
    {"name", "text", "–", "required", "unique"},
    {"type", "choice", "–", "required", "ground_contact"},
    {"body", "text", "–", "required", "the body that touches the ground"},
    {"point", "vector", "m", "`[0, 0, 0]`", "the contact point, body frame"},
    {"stiffness", "number", "N/m", "required", "k_f > 0"},
    {"damping", "number", "N s/m", "0", "c_f"},
    {"preload", "number", "N", "0", "contact force at the initial state"},
    {"description", "text", "–", "–", "free text"},
};

}  // namespace

std::span<const KeySpec> GroundContactDefinition::keys() { return ground_contact_keys; }

GroundContactDefinition GroundContactDefinition::read(const NodeReader& item, const CaseDefinition&) {
  GroundContactDefinition def;
  item.expect_section(type);
  def.body = item["body"].text();
  def.stiffness = item["stiffness"].positive_number();
  def.damping = item.optional("damping") ? item["damping"].non_negative_number() : 0.0;
  def.preload = item.optional("preload") ? item["preload"].non_negative_number() : 0.0;
  if (auto p = item.optional("point")) def.point = p->vector3_in(length_range);
  return def;
}

void GroundContactDefinition::build(const std::string& name, SceneBuildContext& context) const {
  const BodyPoint contact_point = context.body_point(name, "body", body, point);
  if (contact_point.link == 0)
    throw context.error(name, "body", "'ground'", "the name of the body that touches the ground");
  GroundContactParameters parameters{stiffness, damping, 0.0};
  // The system's Data holds the positions of the assembled initial state q0 (the scene
  // updates them before this stage).
  parameters.surface_height = contact_point.position_world(context.system.data()).z() + preload / stiffness;
  context.summarised.ground_contacts.push_back(
      add_element(context.system, std::make_unique<GroundContact>(name, contact_point, parameters)));
}

}  // namespace heavesim
