#include "samples/planar_chains.hpp"

#include "kernel/model/model_builder.hpp"
#include "samples/joint_definition.hpp"

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
    builder.add_joint(joint_definition("pin" + std::to_string(i + 1), JointKind::revolute,
                                       i == 0 ? "ground" : "link" + std::to_string(i), "link" + std::to_string(i + 1),
                                       Vector3::UnitY(), Vector3(0.0, 0.0, i == 0 ? 0.0 : -links[i - 1].length)));
  }
  return builder.build();
}

Model pendulum(double mass, double com_distance, double inertia_about_com) {
  ModelBuilder builder;
  builder.add_body({"rod",
                    Inertia(mass, Vector3(0, 0, -com_distance),
                            Vector3(inertia_about_com, inertia_about_com, 0.0).asDiagonal()),
                    std::nullopt});
  builder.add_joint(joint_definition("pin", JointKind::revolute, "ground", "rod", Vector3::UnitY()));
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
