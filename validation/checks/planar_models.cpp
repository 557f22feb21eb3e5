#include "validation/checks/planar_models.hpp"

#include "kernel/model/model_builder.hpp"

namespace heavesim::validation {

Model planar_chain_model(const std::vector<oracle::PlanarLink>& links, double gravity) {
  ModelBuilder builder;
  builder.set_gravity(Vector3(0.0, 0.0, -gravity));
  for (std::size_t i = 0; i < links.size(); ++i) {
    const oracle::PlanarLink& link = links[i];
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

double relative_error(const VectorX& a, const VectorX& b, double floor) {
  return (a - b).norm() / std::max(b.norm(), floor);
}

}  // namespace heavesim::validation
