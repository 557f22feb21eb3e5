// Contact points of the shape pairs (kernel/contact/contact_detection.hpp) against the
// positions worked out by hand for each placement, and the refusals of
// check_contact_model.
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/algorithms/kinematics.hpp"
#include "kernel/contact/contact_detection.hpp"
#include "kernel/model/model_builder.hpp"
#include "kernel/parameter_error.hpp"
#include "samples/contact_scenes.hpp"
#include "samples/joint_definition.hpp"

namespace heavesim {
namespace {

std::vector<ContactPoint> detect(const samples::ContactScene& scene, const VectorX& q) {
  Data data(*scene.model);
  update_positions(*scene.model, data, q);
  std::vector<ContactPoint> points(64);
  const int found = detect_contacts(*scene.model, data, scene.contacts, points);
  EXPECT_LE(found, 64);
  points.resize(found);
  return points;
}

TEST(ContactDetection, BoxOnPlaneTouchesAtItsFourLowerCorners) {
  const samples::ContactScene scene = samples::box_stack(1, 2.0, 1.0, 1.0, 0.5);
  const std::vector<ContactPoint> points = detect(scene, scene.q);
  ASSERT_EQ(points.size(), 4u);
  for (const ContactPoint& c : points) {
    EXPECT_NEAR(c.gap, 0.0, 1e-14);
    EXPECT_NEAR(c.point_world.z(), 0.0, 1e-14);
    EXPECT_NEAR(std::abs(c.point_world.x()), 1.0, 1e-14);
    EXPECT_NEAR(std::abs(c.point_world.y()), 1.0, 1e-14);
    EXPECT_TRUE(c.normal_world.isApprox(Vector3::UnitZ()));
    EXPECT_NEAR(c.tangent1_world.dot(c.normal_world), 0.0, 1e-15);
    EXPECT_TRUE(c.normal_world.cross(c.tangent1_world).isApprox(c.tangent2_world));
  }
  // Raised by 0.4 mm (inside the 1 mm margin) the same corners come with that gap; by
  // 2 mm none does.
  VectorX q = scene.q;
  q[2] += 4e-4;
  for (const ContactPoint& c : detect(scene, q)) EXPECT_NEAR(c.gap, 4e-4, 1e-15);
  q[2] += 1.6e-3;
  EXPECT_TRUE(detect(scene, q).empty());
}

TEST(ContactDetection, StackedCubesTouchAtFourPointsPerFaceOnce) {
  // Equal footprints: the corners of each box meet the corners of the one below; the two
  // passes (a's corners on b's face, b's on a's) find the same four points, kept once.
  const samples::ContactScene scene = samples::box_stack(3, 1.0, 1.0, 1.0, 0.5);
  const std::vector<ContactPoint> points = detect(scene, scene.q);
  ASSERT_EQ(points.size(), 12u);
  for (int face = 0; face < 3; ++face) {
    int on_face = 0;
    for (const ContactPoint& c : points)
      if (c.pair == face) {
        ++on_face;
        EXPECT_NEAR(c.point_world.z(), face * 1.0, 1e-14);
        EXPECT_TRUE(c.normal_world.isApprox(Vector3::UnitZ())) << c.normal_world.transpose();
      }
    EXPECT_EQ(on_face, 4);
  }
}

TEST(ContactDetection, SmallBoxTurnedOnABigBoxTouchesAtItsOwnCorners) {
  samples::ContactScene scene = samples::box_stack(2, 1.0, 1.0, 1.0, 0.5);
  // The upper box: half size 0.2, turned 45 degrees about z, 1e-4 m above the top face.
  ContactModel& contacts = scene.contacts;
  contacts.geometries[2].shape.half_extents = Vector3::Constant(0.2);
  VectorX q = scene.q;
  const int qi = scene.model->joints[scene.model->link_index("box1")].q_index;
  q.segment<3>(qi) = Vector3(0.1, -0.05, 1.0 + 0.2 + 1e-4);
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(M_PI / 4, Vector3::UnitZ()));
  q.segment<4>(qi + 3) << turn.w(), turn.x(), turn.y(), turn.z();
  int upper = 0;
  for (const ContactPoint& c : detect(scene, q))
    if (c.pair == 1) {
      ++upper;
      EXPECT_NEAR(c.gap, 1e-4, 1e-13);
      EXPECT_NEAR(c.point_world.z(), 1.0 + 0.5e-4, 1e-13);
      EXPECT_NEAR(std::hypot(c.point_world.x() - 0.1, c.point_world.y() + 0.05), 0.2 * std::sqrt(2.0), 1e-12);
    }
  EXPECT_EQ(upper, 4);
}

TEST(ContactDetection, SphereOnPlaneAndOnABoxEdge) {
  samples::ContactScene scene = samples::sphere_on_plane(0.5, 1.0, 0.5 - 2e-4, 0.3, 0.0);
  std::vector<ContactPoint> points = detect(scene, scene.q);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_NEAR(points[0].gap, -2e-4, 1e-15);
  EXPECT_NEAR(points[0].point_world.z(), -1e-4, 1e-15);
  // Pair given as (plane, sphere): the normal turns round, pushing the plane (a) away.
  std::swap(scene.contacts.pairs[0].geometry_a, scene.contacts.pairs[0].geometry_b);
  points = detect(scene, scene.q);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_TRUE(points[0].normal_world.isApprox(-Vector3::UnitZ()));
  EXPECT_EQ(points[0].link_a, 0);

  // A sphere near the edge x = 1, z = 1 of a box: closest point on the edge.
  samples::ContactScene edge = samples::box_stack(1, 2.0, 1.0, 1.0, 0.0);
  ModelBuilder builder;
  ContactGeometry ball;
  ball.name = "ball";
  ball.link = 0;  // fixed in the world beside the box
  ball.shape.kind = ContactShapeKind::sphere;
  ball.shape.radius = 0.3;
  const Vector3 direction = Vector3(1, 0, 1).normalized();
  ball.X_link_shape = Transform::from_translation(Vector3(1, 0, 2) + (0.3 + 5e-4) * direction);
  edge.contacts.geometries.push_back(ball);
  edge.contacts.pairs = {{"ball_on_box", 2, 1, 0.0, 0.0}};
  points = detect(edge, edge.q);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_NEAR(points[0].gap, 5e-4, 1e-14);
  EXPECT_TRUE(points[0].normal_world.isApprox(direction, 1e-12));
}

TEST(ContactDetection, CylinderLyingAndStandingOnPlane) {
  ModelBuilder builder;
  builder.add_body({"pipe", Inertia(100.0, Vector3::Zero(), Matrix3::Identity()), std::nullopt});
  builder.add_joint(samples::joint_definition("pipe_free", JointKind::free, "ground", "pipe"));
  samples::ContactScene scene;
  scene.model = std::make_shared<const Model>(builder.build());
  ContactGeometry plane;
  plane.name = "deck";
  plane.shape.kind = ContactShapeKind::plane;
  ContactGeometry pipe;
  pipe.name = "pipe";
  pipe.link = 1;
  pipe.shape.kind = ContactShapeKind::cylinder;
  pipe.shape.radius = 0.25;
  pipe.shape.half_length = 6.0;
  scene.contacts.geometries = {plane, pipe};
  scene.contacts.pairs = {{"pipe_on_deck", 1, 0, 0.3, 0.0}};
  // Lying along x (its z axis turned onto x), axis 0.25 m up: two points, one per end.
  VectorX q = scene.model->neutral_configuration();
  const Eigen::Quaterniond lying(Eigen::AngleAxisd(M_PI / 2, Vector3::UnitY()));
  q.head<3>() = Vector3(0, 0, 0.25);
  q.segment<4>(3) << lying.w(), lying.x(), lying.y(), lying.z();
  std::vector<ContactPoint> points = detect(scene, q);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_NEAR(std::abs(points[0].point_world.x()), 6.0, 1e-12);
  EXPECT_NEAR(points[0].point_world.x(), -points[1].point_world.x(), 1e-12);
  for (const ContactPoint& c : points) EXPECT_NEAR(c.gap, 0.0, 1e-14);
  // Standing on an end: four rim points at radius 0.25.
  q = scene.model->neutral_configuration();
  q[2] = 6.0;
  points = detect(scene, q);
  ASSERT_EQ(points.size(), 4u);
  for (const ContactPoint& c : points) EXPECT_NEAR(c.point_world.head<2>().norm(), 0.25, 1e-14);
}

TEST(ContactDetection, CheckNamesTheBadItem) {
  const samples::ContactScene scene = samples::sphere_on_plane(0.5, 1.0, 0.5, 0.3, 0.0);
  const auto expect_refused = [&](const ContactModel& contacts, const std::string& field, const std::string& found) {
    try {
      check_contact_model(*scene.model, contacts);
      ADD_FAILURE() << "accepted; expected a refusal of " << field;
    } catch (const ParameterError& error) {
      EXPECT_EQ(error.field(), field);
      EXPECT_NE(error.found().find(found), std::string::npos) << error.what();
    }
  };
  ContactModel bad = scene.contacts;
  bad.pairs[0].friction_coefficient = -0.1;
  expect_refused(bad, "pairs[0].friction_coefficient", "-0.1 (pair 'ball' with 'ground')");
  bad = scene.contacts;
  bad.pairs[0].restitution = 1.5;
  expect_refused(bad, "pairs[0].restitution", "1.5");
  bad = scene.contacts;
  bad.geometries[1].shape.radius = 0.0;
  expect_refused(bad, "geometries[1].radius", "0");
  bad = scene.contacts;
  bad.geometries[1].shape.kind = ContactShapeKind::plane;
  expect_refused(bad, "pairs[0]", "plane with plane");
  bad = scene.contacts;
  bad.joint_stops.push_back({"float_stop", 1, 0.0, 1.0, 0.0});
  expect_refused(bad, "joint_stops[0].joint", "'ball_free' with 6 velocity coordinates");
  EXPECT_NO_THROW(check_contact_model(*scene.model, scene.contacts));
}

}  // namespace
}  // namespace heavesim
