#include "samples/loop_mechanisms.hpp"

#include "kernel/model/model_builder.hpp"
#include "samples/joint_definition.hpp"

namespace heavesim::samples {

std::shared_ptr<const Model> parallelogram_four_bar() {
  ModelBuilder builder;
  const Inertia rod(1.0, Vector3(0.5, 0, 0), Vector3(0, 1.0 / 12, 1.0 / 12).asDiagonal().toDenseMatrix());
  for (const char* name : {"crank", "coupler", "rocker"}) builder.add_body({name, rod, std::nullopt});
  auto revolute = [](std::string name, std::string parent, std::string child, const Vector3& at) {
    return joint_definition(std::move(name), JointKind::revolute, std::move(parent), std::move(child),
                            Vector3::UnitZ(), at);
  };
  builder.add_joint(revolute("pivot_a", "ground", "crank", Vector3::Zero()));
  builder.add_joint(revolute("pin", "crank", "coupler", Vector3(1, 0, 0)));
  builder.add_joint(revolute("pivot_b", "ground", "rocker", Vector3(0, 1, 0)));
  LoopJointDefinition closure;
  closure.name = "closure";
  closure.parent = "coupler";
  closure.child = "rocker";
  closure.X_parent_joint = Transform::from_translation(Vector3(0, 1, 0));
  closure.X_child_joint = Transform::from_translation(Vector3(1, 0, 0));
  builder.add_loop_joint(closure);
  return std::make_shared<const Model>(builder.build());
}

std::shared_ptr<const Model> tethered_slider_pendulum() {
  ModelBuilder builder;
  builder.set_gravity(Vector3(0, 0, -9.81));
  builder.add_body({"slider", Inertia(1.0, Vector3::Zero(), Matrix3::Identity()), std::nullopt});
  builder.add_body({"rod", Inertia(1.0, Vector3(0, 0, -0.5), Matrix3::Identity() * 0.1), std::nullopt});
  builder.add_joint(joint_definition("rail", JointKind::prismatic, "ground", "slider", Vector3::UnitX()));
  builder.add_joint(joint_definition("pin", JointKind::revolute, "slider", "rod", Vector3::UnitY()));
  builder.add_distance_constraint({"tether", "ground", "rod", Vector3::Zero(), Vector3(0, 0, -1), 1.0});
  DriverDefinition push;
  push.name = "push";
  push.joint = "rail";
  push.motion = [](double t) { return DriverMotion{1.0 + t, 1.0, 0.0}; };
  builder.add_driver(push);
  return std::make_shared<const Model>(builder.build());
}

Model overconstrained_rails() {
  ModelBuilder builder;
  for (const char* body : {"rod_a", "rod_b", "block"})
    builder.add_body({body, Inertia(1.0, Vector3::Zero(), Matrix3::Identity()), std::nullopt});
  builder.add_joint(
      joint_definition("slide_a", JointKind::prismatic, "ground", "rod_a", Vector3::UnitZ(), Vector3(-1, 0, 0)));
  builder.add_joint(
      joint_definition("slide_b", JointKind::prismatic, "ground", "rod_b", Vector3::UnitZ(), Vector3(1, 0, 0)));
  JointDefinition weld = joint_definition("weld_a", JointKind::fixed, "rod_a", "block");
  weld.X_child_joint = Transform::from_translation(Vector3(-1, 0, 0));
  builder.add_joint(weld);
  LoopJointDefinition tie;
  tie.name = "weld_b";
  tie.kind = JointKind::fixed;
  tie.parent = "rod_b";
  tie.child = "block";
  tie.X_child_joint = Transform::from_translation(Vector3(1, 0, 0));
  builder.add_loop_joint(tie);
  return builder.build();
}

}  // namespace heavesim::samples
