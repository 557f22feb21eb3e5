#include "samples/hanging_chain.hpp"

#include "kernel/model/model_builder.hpp"

namespace heavesim::samples {

Model hanging_chain(const std::vector<double>& masses) {
  ModelBuilder builder;
  for (std::size_t i = 0; i < masses.size(); ++i) {
    const std::string name = "b" + std::to_string(i);
    builder.add_body({name, Inertia(masses[i], Vector3(0.0, 0.0, -0.5), Vector3(0.2, 0.3, 0.25).asDiagonal()),
                      std::nullopt});
    JointDefinition joint;
    joint.name = "j" + std::to_string(i);
    joint.kind = i % 2 ? JointKind::spherical : JointKind::revolute;
    joint.axis = Vector3::UnitX();
    joint.parent = i == 0 ? "ground" : "b" + std::to_string(i - 1);
    joint.child = name;
    joint.X_parent_joint = Transform::from_translation(Vector3(0, 0, i == 0 ? 0.0 : -1.0));
    builder.add_joint(joint);
  }
  return builder.build();
}

}  // namespace heavesim::samples
