#include "samples/oscillators.hpp"

#include "kernel/model/model_builder.hpp"
#include "samples/joint_definition.hpp"

namespace heavesim::samples {
namespace {

JointDefinition vertical_prismatic(std::string name, std::string parent, std::string child) {
  return joint_definition(std::move(name), JointKind::prismatic, std::move(parent), std::move(child),
                          Vector3::UnitZ());
}

BodyDefinition point_body(std::string name, double mass) {
  return {std::move(name), Inertia(mass, Vector3::Zero(), Matrix3::Identity() * mass), std::nullopt};
}

}  // namespace

Model prismatic_oscillator(double mass, double stiffness, std::optional<JointLimits> limits, const Vector3& gravity) {
  ModelBuilder builder;
  builder.set_gravity(gravity);
  builder.add_body({"block", Inertia(mass, Vector3::Zero(), Matrix3::Identity()), std::nullopt});
  JointDefinition slide = vertical_prismatic("slide", "ground", "block");
  slide.limits = limits;
  if (stiffness > 0.0)
    slide.spring = JointSpringDamper{JointVector::Constant(1, stiffness), JointVector::Zero(1), JointVector::Zero(1)};
  builder.add_joint(slide);
  return builder.build();
}

std::shared_ptr<const Model> vertical_slider(double mass, const Vector3& gravity) {
  ModelBuilder builder;
  builder.set_gravity(gravity);
  builder.add_body(point_body("load", mass));
  builder.add_joint(vertical_prismatic("stroke", ModelBuilder::ground_name, "load"));
  return std::make_shared<const Model>(builder.build());
}

std::shared_ptr<const Model> base_and_load(double base_mass, double load_mass, const Vector3& gravity) {
  ModelBuilder builder;
  builder.set_gravity(gravity);
  builder.add_body(point_body("base", base_mass));
  builder.add_body(point_body("load", load_mass));
  builder.add_joint(vertical_prismatic("heave", ModelBuilder::ground_name, "base"));
  builder.add_joint(vertical_prismatic("stroke", "base", "load"));
  return std::make_shared<const Model>(builder.build());
}

}  // namespace heavesim::samples
