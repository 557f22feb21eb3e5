#include "app/case/element_reader.hpp"

namespace heavesim {

void read_kernel_force(const NodeReader& item, const std::string& type, const std::string& name,
                       CaseDefinition& definition) {
  ForceDefinition def;
  def.type = type == "spring_damper"    ? ForceDefinition::Type::spring_damper
             : type == "ground_contact" ? ForceDefinition::Type::ground_contact
                                        : ForceDefinition::Type::point_force;
  def.name = name;
  item.expect_section(type);
  if (def.type == ForceDefinition::Type::ground_contact) {
    // A unilateral spring-damper on an earth-fixed horizontal surface (the bit on the
    // formation, docs/physics/drilling-rig.md §2), preloaded at the initial state.
    def.body_a = item["body"].text();
    def.spring.stiffness = item["stiffness"].positive_number();
    def.spring.damping = item.optional("damping") ? item["damping"].non_negative_number() : 0.0;
    def.preload = item.optional("preload") ? item["preload"].non_negative_number() : 0.0;
  } else if (def.type == ForceDefinition::Type::spring_damper) {
    def.body_a = item["body_a"].text();
    def.body_b = item["body_b"].text();
    if (auto point = item.optional("point_b")) def.point_b = point->vector3();
    def.spring.stiffness = item.optional("stiffness") ? item["stiffness"].non_negative_number() : 0.0;
    def.spring.damping = item.optional("damping") ? item["damping"].non_negative_number() : 0.0;
    def.spring.rest_length = item["rest_length"].non_negative_number();
  } else {
    def.body_a = item["body"].text();
    def.force_world = item["force"].vector3();
  }
  if (auto point = item.optional(def.type == ForceDefinition::Type::spring_damper ? "point_a" : "point"))
    def.point_a = point->vector3();
  definition.item_paths[def.name] = item.path();
  definition.forces.push_back(std::move(def));
}

}  // namespace heavesim
