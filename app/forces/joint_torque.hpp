#pragma once
// Force kind `joint_torque`: a generalized force tau(t) on one coordinate of a joint of
// the tree -- a motor torque [N m] on a rotation, a force [N] on a translation -- as a
// muParser expression of time t [s] and the case's parameters, parsed as a driver's
// `position` is (app/case/time_function.hpp). Kernel element: kernel/elements/joint_torque.hpp.
#include <memory>

#include "app/case/time_function.hpp"
#include "app/forces/force_kind.hpp"

namespace heavesim {

struct JointTorqueDefinition {
  static constexpr std::string_view type = "joint_torque";
  static constexpr BuildStage stage = BuildStage::on_model;
  static std::span<const KeySpec> keys();
  static std::span<const SchemaSection> sub_sections() { return {}; }
  static JointTorqueDefinition read(const NodeReader& item, const CaseDefinition& definition);
  void build(const std::string& name, SceneBuildContext& context) const;

  std::string joint;                          // a revolute, prismatic, cylindrical or universal joint
  int coordinate = 0;                         // which of its coordinates (0 for a 1-DoF joint)
  std::shared_ptr<const TimeFunction> torque;  // tau(t) [N m or N], parsed from its expression of t
};

}  // namespace heavesim
