#pragma once
// One way for the sample models to declare a tree joint: name, kind, the two bodies,
// the axis (joint frame) and where the joint frame sits in the parent body frame; the
// rest of JointDefinition keeps its defaults (child frame = joint frame, no spring, no
// limits) and a caller sets it afterwards where a model needs it.
#include <string>

#include "kernel/model/model_builder.hpp"

namespace heavesim::samples {

inline JointDefinition joint_definition(std::string name, JointKind kind, std::string parent, std::string child,
                                        const Vector3& axis = Vector3::UnitZ(),
                                        const Vector3& position_in_parent = Vector3::Zero()) {
  JointDefinition joint;
  joint.name = std::move(name);
  joint.kind = kind;
  joint.axis = axis;
  joint.parent = std::move(parent);
  joint.child = std::move(child);
  joint.X_parent_joint = Transform::from_translation(position_in_parent);
  return joint;
}

}  // namespace heavesim::samples
