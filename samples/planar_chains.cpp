#include "samples/planar_chains.hpp"

#include "kernel/model/model_builder.hpp"

namespace heavesim::samples {

Model planar_chain(const std::vector<PlanarLink>& links, double gravity) {
  ModelBuilder builder;
  builder.set_gravity(Vector3(0.0, 0.0, -gravity));
  for (std::size_t i = 0; i < links.size(); ++i) {
    const PlanarLink& link = links[i];
    // Slender rod about its CoM: I about the two transverse axes, (almost) nothing axially.
    const Matrix3 inertia = Eigen::Vector3d(link.inertia, link.inertia, 0.0).asDiagonal();
    builder.add_body({"link" + std::to_string(i + 1), Inertia(link.mass, Vector3(0.0, 0.0, -link.com), inertia),
                      std::nullopt});
    JointDefinition joint;
    joint.name = "pin" + std::to_string(i + 1);
    joint.kind = JointKind::revolute;
    joint.axis = Vector3::UnitY();
    joint.parent = i == 0 ? "ground" : "link" + std::to_string(i);
    joint.child = "link" + std::to_string(i + 1);
    joint.X_parent_joint = Transform::from_translation(Vector3(0.0, 0.0, i == 0 ? 0.0 : -links[i - 1].length));
    builder.add_joint(joint);
  }
  return builder.build();
}

Model pendulum(double mass, double com_distance, double inertia_about_com) {
  ModelBuilder builder;
  builder.add_body({"rod",
                    Inertia(mass, Vector3(0, 0, -com_distance),
                            Vector3(inertia_about_com, inertia_about_com, 0.0).asDiagonal()),
                    std::nullopt});
  JointDefinition pin;
  pin.name = "pin";
  pin.axis = Vector3::UnitY();
  pin.parent = "ground";
  pin.child = "rod";
  builder.add_joint(pin);
  return builder.build();
}

VectorX relative_from_absolute(const VectorX& theta) {
  VectorX q = theta;
  for (Eigen::Index i = 1; i < theta.size(); ++i) q[i] = theta[i] - theta[i - 1];
  return q;
}

VectorX absolute_from_relative(const VectorX& q) {
  VectorX theta = q;
  for (Eigen::Index i = 1; i < q.size(); ++i) theta[i] = theta[i - 1] + q[i];
  return theta;
}

}  // namespace heavesim::samples
