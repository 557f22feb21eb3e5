#include "samples/random_models.hpp"

#include <cmath>

#include "kernel/algorithms/configuration.hpp"
#include "kernel/model/model_builder.hpp"

namespace heavesim::samples {
namespace {

double uniform(std::mt19937_64& random, double low, double high) {
  return std::uniform_real_distribution<double>(low, high)(random);
}

Vector3 random_vector(std::mt19937_64& random, double scale) {
  return Vector3(uniform(random, -scale, scale), uniform(random, -scale, scale), uniform(random, -scale, scale));
}

Matrix3 random_rotation(std::mt19937_64& random) {
  Eigen::Quaterniond q(uniform(random, -1, 1), uniform(random, -1, 1), uniform(random, -1, 1), uniform(random, -1, 1));
  return q.normalized().toRotationMatrix();
}

Vector3 random_unit(std::mt19937_64& random) { return random_vector(random, 1.0).normalized(); }

}  // namespace

Model random_tree(std::mt19937_64& random, const RandomTreeOptions& options) {
  ModelBuilder builder;
  builder.set_gravity(Vector3(0.3, -0.2, -9.81));
  for (int b = 0; b < options.bodies; ++b) {
    const std::string name = "body" + std::to_string(b);
    // Principal moments in [0.5, 1] always satisfy the triangle inequality.
    const Matrix3 R = random_rotation(random);
    const Matrix3 inertia =
        R * Vector3(uniform(random, 0.5, 1.0), uniform(random, 0.5, 1.0), uniform(random, 0.5, 1.0)).asDiagonal() *
        R.transpose();
    BodyDefinition body{name, Inertia(uniform(random, 0.5, 3.0), random_vector(random, 0.5), inertia), std::nullopt};
    if (options.added_inertia && b % 3 == 1) {
      const Matrix6 B = Matrix6::Random();
      body.added_inertia = B * B.transpose() + 0.1 * Matrix6::Identity();
    }
    builder.add_body(body);

    JointDefinition joint;
    joint.name = "joint" + std::to_string(b);
    joint.child = name;
    const int parent = options.chain ? b - 1 : std::uniform_int_distribution<int>(-1, b - 1)(random);
    joint.parent = parent < 0 ? "ground" : "body" + std::to_string(parent);
    joint.X_parent_joint = Transform(random_rotation(random), random_vector(random, 1.0));
    joint.X_child_joint = Transform(random_rotation(random), random_vector(random, 0.3));
    // Cycle through every kind; axial and universal joints get random (unit) axes.
    static constexpr JointKind kinds[7] = {JointKind::fixed,     JointKind::revolute,  JointKind::prismatic,
                                           JointKind::cylindrical, JointKind::universal, JointKind::spherical,
                                           JointKind::free};
    joint.kind = options.only_revolute ? JointKind::revolute : kinds[b % 7];
    joint.axis = random_unit(random);
    joint.second_axis = joint.axis.unitOrthogonal();
    const JointType type = canonical_joint_type(joint.kind);
    if (options.joint_springs && joint_has_scalar_coordinates(type) && joint_nv(type) > 0) {
      const int nv = joint_nv(type);
      joint.spring = JointSpringDamper{JointVector::Constant(nv, uniform(random, 1.0, 10.0)),
                                       JointVector::Constant(nv, uniform(random, 0.1, 1.0)),
                                       JointVector::Constant(nv, uniform(random, -0.5, 0.5))};
    }
    builder.add_joint(joint);
  }
  if (options.constraints) {
    // Loop joints of every constraining kind between random pairs of bodies (not
    // assembled: the equations and their derivatives hold at any configuration).
    const JointKind loop_kinds[6] = {JointKind::fixed,       JointKind::revolute,  JointKind::prismatic,
                                     JointKind::cylindrical, JointKind::universal, JointKind::spherical};
    std::uniform_int_distribution<int> pick(-1, options.bodies - 1);
    auto body_name = [](int b) { return b < 0 ? std::string("ground") : "body" + std::to_string(b); };
    for (int k = 0; k < 6; ++k) {
      LoopJointDefinition loop;
      loop.name = "loop" + std::to_string(k);
      loop.kind = loop_kinds[k];
      loop.axis = random_unit(random);
      loop.second_axis = loop.axis.unitOrthogonal();
      int a = pick(random), b = pick(random);
      while (b == a) b = pick(random);
      loop.parent = body_name(a);
      loop.child = body_name(b);
      loop.X_parent_joint = Transform(random_rotation(random), random_vector(random, 0.5));
      loop.X_child_joint = Transform(random_rotation(random), random_vector(random, 0.5));
      builder.add_loop_joint(loop);
    }
    builder.add_distance_constraint({"rod", "body0", "body" + std::to_string(options.bodies - 1),
                                     random_vector(random, 0.3), random_vector(random, 0.3), 1.3});
    builder.add_coupler({"gear", "joint1", options.bodies > 8 ? "joint8" : "joint2", -0.7, 0.2});
    // joint3 is cylindrical (kinds[3]): prescribe its translation.
    DriverDefinition push;
    push.name = "push";
    push.joint = "joint3";
    push.coordinate = 1;
    push.motion = [](double t) {
      return DriverMotion{0.2 * std::sin(1.3 * t) + 0.1 * t * t, 0.26 * std::cos(1.3 * t) + 0.2 * t,
                          -0.338 * std::sin(1.3 * t) + 0.2};
    };
    builder.add_driver(push);
    // The drivers on frames, at fixed points and frames (no draws: the random sequence
    // of the tree and of the states drawn after it stays as it was).
    DriverDefinition slide;
    slide.name = "slide";
    slide.motion = [](double t) {
      return DriverMotion{0.5 + 0.3 * std::sin(0.9 * t), 0.27 * std::cos(0.9 * t), -0.243 * std::sin(0.9 * t)};
    };
    slide.kind = DriverKind::absolute;
    slide.body_b = "body2";
    slide.X_body_b_frame = Transform::from_translation(Vector3(0.1, -0.2, 0.3));
    slide.direction = Vector3(1.0, 2.0, 2.0) / 3.0;
    builder.add_driver(slide);
    DriverDefinition stretch;
    stretch.name = "stretch";
    stretch.motion = [](double t) { return DriverMotion{1.1 + 0.2 * t * t, 0.4 * t, 0.4}; };
    stretch.kind = DriverKind::distance;
    stretch.body_a = "ground";
    stretch.X_body_a_frame = Transform::from_translation(Vector3(0.2, 0.1, 0.0));
    stretch.body_b = "body" + std::to_string(options.bodies - 1);
    stretch.X_body_b_frame = Transform::from_translation(Vector3(0.0, 0.1, -0.2));
    builder.add_driver(stretch);
    DriverDefinition twist;
    twist.name = "twist";
    twist.motion = [](double t) { return DriverMotion{0.7 * t + 0.3 * std::sin(t), 0.7 + 0.3 * std::cos(t), -0.3 * std::sin(t)}; };
    twist.kind = DriverKind::angle;
    twist.body_a = "body1";
    twist.X_body_a_frame =
        Transform(Eigen::AngleAxisd(0.4, Vector3(1.0, 1.0, 0.0).normalized()).toRotationMatrix(), Vector3(0.1, 0.0, 0.0));
    twist.body_b = "body" + std::to_string(options.bodies - 2);
    twist.X_body_b_frame =
        Transform(Eigen::AngleAxisd(-0.7, Vector3(0.0, 1.0, 2.0).normalized()).toRotationMatrix(), Vector3::Zero());
    builder.add_driver(twist);
  }
  return builder.build();
}

RandomState random_state(const Model& model, std::mt19937_64& random) {
  RandomState state;
  const VectorX q0 = model.neutral_configuration();
  VectorX displacement(model.nv);
  for (int i = 0; i < model.nv; ++i) displacement[i] = uniform(random, -1.5, 1.5);
  state.q = q0;
  integrate_configuration(model, q0, displacement, 1.0, state.q);
  state.v = VectorX(model.nv);
  state.tau = VectorX(model.nv);
  for (int i = 0; i < model.nv; ++i) {
    state.v[i] = uniform(random, -2.0, 2.0);
    state.tau[i] = uniform(random, -5.0, 5.0);
  }
  state.external_forces.assign(model.num_links(), Force::Zero());
  for (int i = 1; i < model.num_links(); ++i)
    state.external_forces[i] = Force(random_vector(random, 3.0), random_vector(random, 10.0));
  return state;
}

RandomTreeAndState random_tree_and_state(std::mt19937_64& random, int bodies, bool added_inertia, bool chain) {
  RandomTreeOptions options;
  options.bodies = bodies;
  options.added_inertia = added_inertia;
  options.chain = chain;
  Model model = random_tree(random, options);
  RandomState state = random_state(model, random);  // after the tree: the same draws as calling both in turn
  return {std::move(model), std::move(state)};
}

}  // namespace heavesim::samples
