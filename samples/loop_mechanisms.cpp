#include "samples/loop_mechanisms.hpp"

#include "kernel/model/model_builder.hpp"

namespace heavesim::samples {

std::shared_ptr<const Model> parallelogram_four_bar() {
  ModelBuilder builder;
  const Inertia rod(1.0, Vector3(0.5, 0, 0), Vector3(0, 1.0 / 12, 1.0 / 12).asDiagonal().toDenseMatrix());
  for (const char* name : {"crank", "coupler", "rocker"}) builder.add_body({name, rod, std::nullopt});
  auto revolute = [](std::string name, std::string parent, std::string child, const Vector3& at) {
    JointDefinition joint;
    joint.name = std::move(name);
    joint.parent = std::move(parent);
    joint.child = std::move(child);
    joint.X_parent_joint = Transform::from_translation(at);
    return joint;
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
  JointDefinition rail, pin;
  rail.name = "rail";
  rail.kind = JointKind::prismatic;
  rail.axis = Vector3::UnitX();
  rail.parent = "ground";
  rail.child = "slider";
  pin.name = "pin";
  pin.kind = JointKind::revolute;
  pin.axis = Vector3::UnitY();
  pin.parent = "slider";
  pin.child = "rod";
  builder.add_joint(rail);
  builder.add_joint(pin);
  builder.add_distance_constraint({"tether", "ground", "rod", Vector3::Zero(), Vector3(0, 0, -1), 1.0});
  builder.add_driver({"push", "rail", 0, [](double t) { return DriverMotion{1.0 + t, 1.0, 0.0}; }});
  return std::make_shared<const Model>(builder.build());
}

Model overconstrained_rails() {
  ModelBuilder builder;
  for (const char* body : {"rod_a", "rod_b", "block"})
    builder.add_body({body, Inertia(1.0, Vector3::Zero(), Matrix3::Identity()), std::nullopt});
  JointDefinition slide_a, slide_b, weld;
  slide_a.name = "slide_a";
  slide_a.kind = JointKind::prismatic;
  slide_a.parent = "ground";
  slide_a.child = "rod_a";
  slide_a.X_parent_joint = Transform::from_translation(Vector3(-1, 0, 0));
  slide_b = slide_a;
  slide_b.name = "slide_b";
  slide_b.child = "rod_b";
  slide_b.X_parent_joint = Transform::from_translation(Vector3(1, 0, 0));
  weld.name = "weld_a";
  weld.kind = JointKind::fixed;
  weld.parent = "rod_a";
  weld.child = "block";
  weld.X_child_joint = Transform::from_translation(Vector3(-1, 0, 0));
  builder.add_joint(slide_a);
  builder.add_joint(slide_b);
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
