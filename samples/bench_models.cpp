#include "samples/bench_models.hpp"

#include <random>

#include "kernel/algorithms/configuration.hpp"
#include "kernel/model/model_builder.hpp"

namespace heavesim::samples {

BenchModel bench_double_pendulum() {
  BenchModel model{"double_pendulum", {}};
  for (int i = 0; i < 2; ++i) {
    BenchLink link;
    link.parent = i - 1;
    link.offset = Vector3(0, 0, i == 0 ? 0.0 : -1.0);
    link.axis = Vector3::UnitY();
    link.mass = 1.0;
    link.com = Vector3(0, 0, -0.5);
    link.inertia = Vector3(1.0 / 12, 1.0 / 12, 1e-6);
    model.links.push_back(link);
  }
  return model;
}

namespace {
/// Appends a serial limb of `count` revolute joints with alternating axes.
void add_limb(BenchModel& model, int parent, const Vector3& first_offset, int count, double length) {
  const Vector3 axes[3] = {Vector3::UnitZ(), Vector3::UnitY(), Vector3::UnitX()};
  for (int k = 0; k < count; ++k) {
    BenchLink link;
    link.parent = parent;
    link.offset = k == 0 ? first_offset : Vector3(0, 0, -length);
    link.axis = axes[k % 3];
    link.mass = 3.0 - 0.2 * k;
    link.com = Vector3(0.01 * k, 0.02, -length / 2);
    link.inertia = Vector3(0.05 + 0.005 * k, 0.06, 0.04);
    parent = static_cast<int>(model.links.size());
    model.links.push_back(link);
  }
}

BenchModel limbs_on(bool free_base) {
  BenchModel model{free_base ? "humanoid32" : "tree32_fixed", {}};
  BenchLink torso;
  torso.free = free_base;
  torso.axis = Vector3::UnitZ();
  torso.mass = 30.0;
  torso.com = Vector3(0, 0, 0.2);
  torso.inertia = Vector3(1.2, 1.0, 0.6);
  model.links.push_back(torso);
  const int legs = free_base ? 6 : 6, arms = free_base ? 7 : 7;
  add_limb(model, 0, Vector3(0, 0.1, -0.1), legs, 0.4);
  add_limb(model, 0, Vector3(0, -0.1, -0.1), legs, 0.4);
  add_limb(model, 0, Vector3(0, 0.2, 0.4), arms, 0.3);
  add_limb(model, 0, Vector3(0, -0.2, 0.4), arms, 0.3);
  if (!free_base) {  // 32 revolute joints: the torso joint plus 5 more on a neck/head chain
    add_limb(model, 0, Vector3(0, 0, 0.5), 5, 0.1);
  }
  return model;
}
}  // namespace

BenchModel chain7() {
  BenchModel model{"chain7", {}};
  add_limb(model, -1, Vector3::Zero(), 7, 0.4);
  return model;
}

BenchModel humanoid32() { return limbs_on(true); }
BenchModel tree32_fixed() { return limbs_on(false); }

Model to_model(const BenchModel& bench) {
  ModelBuilder builder;
  for (std::size_t i = 0; i < bench.links.size(); ++i) {
    const BenchLink& link = bench.links[i];
    const std::string name = "link" + std::to_string(i);
    builder.add_body({name, Inertia(link.mass, link.com, link.inertia.asDiagonal()), std::nullopt});
    JointDefinition joint;
    joint.name = "joint" + std::to_string(i);
    joint.kind = link.free ? JointKind::free : JointKind::revolute;
    joint.axis = link.axis;
    joint.parent = link.parent < 0 ? "ground" : "link" + std::to_string(link.parent);
    joint.child = name;
    joint.X_parent_joint = Transform::from_translation(link.offset);
    builder.add_joint(joint);
  }
  return builder.build();
}

BenchStates bench_states(const Model& model, int count, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  auto draw = [&](int size) { return VectorX(VectorX::NullaryExpr(size, [&](Eigen::Index) { return uniform(random); })); };
  const VectorX q0 = model.neutral_configuration();
  BenchStates states;
  for (int k = 0; k < count; ++k) {
    VectorX q(model.nq);
    integrate_configuration(model, q0, draw(model.nv), 1.0, q);
    states.q.push_back(q);
    states.v.push_back(draw(model.nv));
    states.tau.push_back(draw(model.nv));
  }
  return states;
}

}  // namespace heavesim::samples
