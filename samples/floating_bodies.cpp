#include "samples/floating_bodies.hpp"

#include "kernel/model/model_builder.hpp"
#include "samples/joint_definition.hpp"

namespace heavesim::samples {

std::shared_ptr<const Model> free_floating_body(const std::string& body_name, const Inertia& inertia,
                                                const std::optional<Matrix6>& added_inertia, const Vector3& gravity) {
  ModelBuilder builder;
  builder.set_gravity(gravity);
  builder.add_body({body_name, inertia, added_inertia});
  builder.add_joint(joint_definition("float", JointKind::free, "ground", body_name));
  return std::make_shared<const Model>(builder.build());
}

std::shared_ptr<const Model> heaving_mss_semisub(const Matrix6& added_inertia) {
  ModelBuilder builder;
  builder.set_gravity(Vector3(0, 0, -9.81));
  builder.add_body({"semisub",
                    Inertia(mss_semisub_mass, Vector3(0, 0, -0.5), Vector3(5.66e10, 6.01e10, 7.31e10).asDiagonal()),
                    added_inertia});
  builder.add_joint(joint_definition("heave", JointKind::prismatic, "ground", "semisub", Vector3::UnitZ()));
  return std::make_shared<const Model>(builder.build());
}

}  // namespace heavesim::samples
