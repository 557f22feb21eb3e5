// Stroke axes: the joint form and the body form measure the same stroke on the same
// mechanism; the body form's rate is the time derivative of its stroke on a tumbling,
// moving base (checked by differencing positions along a trajectory); and the power of
// the applied force pair is force * ds/dt in both forms (an independent sum over links).
#include <gtest/gtest.h>

#include <cmath>

#include "control/stroke/stroke_axis.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/model/model_builder.hpp"

namespace heavesim {
namespace {

/// Base on a free joint, load on a prismatic joint along a tilted axis of the base.
/// Built here, not in samples/: only this test needs a stroke on a tumbling base.
std::shared_ptr<const Model> tumbling_base() {
  ModelBuilder builder;
  builder.add_body({"base", Inertia(5e4, Vector3(1, 0, 2), Vector3(4e5, 5e5, 6e5).asDiagonal().toDenseMatrix()),
                    std::nullopt});
  builder.add_body({"load", Inertia(3e3, Vector3(0, 0, 0.5), Vector3(1e3, 1e3, 2e2).asDiagonal().toDenseMatrix()),
                    std::nullopt});
  JointDefinition floating;
  floating.name = "float";
  floating.kind = JointKind::free;
  floating.parent = ModelBuilder::ground_name;
  floating.child = "base";
  builder.add_joint(floating);
  JointDefinition slide;
  slide.name = "slide";
  slide.kind = JointKind::prismatic;
  slide.axis = Vector3(0.3, -0.2, 1.0).normalized();
  slide.parent = "base";
  slide.child = "load";
  slide.X_parent_joint = Transform::from_translation(Vector3(0.5, 2.0, 10.0));
  slide.X_child_joint = Transform::from_translation(Vector3(0.0, 0.1, -0.3));
  builder.add_joint(slide);
  return std::make_shared<const Model>(builder.build());
}

struct Trajectory {
  // q(t) = q0 + t v0 on the tangent space is awkward for a quaternion; use a smooth
  // motion through the kernel's own configuration integration instead: fixed v.
  VectorX q0, v;
};

void place(const Model& model, Data& data, const VectorX& q, const VectorX& v) {
  update_positions(model, data, q);
  update_velocities(model, data, q, v);
}

TEST(StrokeAxis, JointAndBodyFormsAgree) {
  auto model = tumbling_base();
  Data data(*model);
  VectorX q = model->neutral_configuration();
  q.head<3>() << 1.0, -2.0, 0.5;
  q.segment<4>(3) = Eigen::Vector4d(0.95, 0.1, -0.2, 0.15).normalized();
  q[7] = 0.7;
  VectorX v(7);
  v << 0.1, -0.05, 0.2, 0.3, -0.4, 0.6, -0.9;
  place(*model, data, q, v);
  const StrokeAxis joint_form = StrokeAxis::on_joint(*model, 2, 0.25);
  // Body form: base point = the joint frame origin on the base, moving point = the
  // joint frame origin on the load, axis = the joint axis in base body axes.
  const StrokeAxis body_form = StrokeAxis::between(*model, BodyPoint::on_body(*model, "base", Vector3(0.5, 2.0, 10.0)),
                                                   BodyPoint::on_body(*model, "load", Vector3(0.0, 0.1, -0.3)),
                                                   Vector3(0.3, -0.2, 1.0).normalized(), 0.25);
  const StrokeMotion a = stroke_motion(joint_form, *model, data);
  const StrokeMotion b = stroke_motion(body_form, *model, data);
  EXPECT_NEAR(a.stroke, 0.7 - 0.25, 1e-12);
  EXPECT_NEAR(a.rate, -0.9, 1e-12);
  EXPECT_NEAR(b.stroke, a.stroke, 1e-12);
  EXPECT_NEAR(b.rate, a.rate, 1e-12);
  const BaseMotion base_a = base_motion(joint_form, *model, data), base_b = base_motion(body_form, *model, data);
  EXPECT_LT((base_a.position_world - base_b.position_world).norm(), 1e-12);
  EXPECT_LT((base_a.velocity_world - base_b.velocity_world).norm(), 1e-12);
  EXPECT_LT((base_a.axis_world - base_b.axis_world).norm(), 1e-12);
}

TEST(StrokeAxis, BodyFormRateIsTheDerivativeOfItsStrokeAndThePairDoesWorkForceTimesRate) {
  auto model = tumbling_base();
  Data data(*model);
  // Body form between a point on the base and a point on the load that is not on the
  // joint line, with an axis different from the joint's: the general case.
  const StrokeAxis axis = StrokeAxis::between(*model, BodyPoint::on_body(*model, "base", Vector3(-1.0, 0.5, 3.0)),
                                              BodyPoint::on_body(*model, "load", Vector3(0.4, -0.2, 1.0)),
                                              Vector3(0.0, 0.6, 0.8), 0.0);
  VectorX q0 = model->neutral_configuration();
  q0.segment<4>(3) = Eigen::Vector4d(0.9, -0.3, 0.2, 0.1).normalized();
  q0[7] = 0.3;
  VectorX v(7);
  v << 0.3, -0.2, 0.5, 1.0, 0.4, -0.7, 0.8;  // constant generalized speeds
  // q(t) along constant v: the free joint integrates on SE(3) exactly for constant body velocity.
  auto configuration = [&](double t) {
    VectorX q(model->nq);
    std::visit([&](const auto& joint) { joint.integrate(q0.data(), v.data(), t, q.data()); }, model->joints[1].type);
    q[7] = q0[7] + t * v[6];
    return q;
  };
  auto stroke_at = [&](double t) {
    place(*model, data, configuration(t), v);
    return stroke_motion(axis, *model, data).stroke;
  };
  const double h = 1e-5;
  const double difference = (stroke_at(0.2 + h) - stroke_at(0.2 - h)) / (2 * h);
  place(*model, data, configuration(0.2), v);
  const StrokeMotion motion = stroke_motion(axis, *model, data);
  EXPECT_NEAR(motion.rate, difference, 1e-8);

  AppliedForces forces(*model);
  apply_stroke_force(axis, *model, data, 1234.5, forces);
  double power = forces.joint_force.dot(v);
  for (int i = 1; i < model->num_links(); ++i) power += dot(data.velocity_world[i], forces.external_force_world[i]);
  EXPECT_NEAR(power, 1234.5 * motion.rate, 1e-9 * 1234.5);
}

}  // namespace
}  // namespace heavesim
