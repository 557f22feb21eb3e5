#include "app/forces/joint_torque.hpp"

#include <memory>

#include "app/case/time_function.hpp"
#include "app/case/motion_reader.hpp"
#include "app/scene/scene_build_context.hpp"
#include "kernel/elements/joint_torque.hpp"

namespace heavesim {
namespace {

constexpr KeySpec joint_torque_keys[] = {
    {"name", "text", "–", "required", "unique"},
    {"type", "choice", "–", "required", "joint_torque"},
    {"joint", "text", "–", "required", "a revolute, prismatic, cylindrical or universal joint of the tree"},
    {"coordinate", "number", "–", "0", "which of its coordinates"},
    {"torque", "expression", "N m or N", "required", "tau(t), along the coordinate"},
    {"description", "text", "–", "–", "free text"},
};

constexpr const char* expected_torque = "an expression of t such as 0.033 or 2*sin(t)";

}  // namespace

std::span<const KeySpec> JointTorqueDefinition::keys() { return joint_torque_keys; }

JointTorqueDefinition JointTorqueDefinition::read(const NodeReader& item, const CaseDefinition&) {
  JointTorqueDefinition def;
  item.expect_section(type);
  def.joint = item["joint"].text();
  def.coordinate = static_cast<int>(item.optional("coordinate") ? item["coordinate"].integer() : 0);
  def.torque = read_time_expression(item["torque"], item["name"].text(), item.expressions(), "joint torque",
                                    expected_torque);
  return def;
}

void JointTorqueDefinition::build(const std::string& name, SceneBuildContext& context) const {
  const Model& model = context.model;
  const int index = model.joint_index(joint);
  if (index <= 0)
    throw context.error(name, "joint", "'" + joint + "', which is not a joint of the tree",
                        "the name of a revolute, prismatic, cylindrical or universal joint (not a loop joint)");
  const Joint& target = model.joints[index];
  if (target.nv == 0 || !joint_has_scalar_coordinates(target.type))
    throw context.error(name, "joint", "a " + joint_type_name(target.type) + " joint",
                        "a revolute, prismatic, cylindrical or universal joint");
  if (coordinate < 0 || coordinate >= target.nv)
    throw context.error(name, "coordinate", std::to_string(coordinate),
                        "0 to " + std::to_string(target.nv - 1) + " (the coordinates of joint '" + joint + "')");
  context.system.add_force_element(std::make_unique<JointTorque>(
      name, target.v_index + coordinate, [function = torque](double t) { return function->position(t); },
      torque->position_uses_time()));
}

}  // namespace heavesim
