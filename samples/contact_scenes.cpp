#include "samples/contact_scenes.hpp"

#include <cmath>

#include "kernel/model/model_builder.hpp"
#include "samples/joint_definition.hpp"

namespace heavesim::samples {

namespace {

Inertia solid_box(double mass, const Vector3& half) {
  const Vector3 edge = 2.0 * half;
  const Vector3 moments(edge.y() * edge.y() + edge.z() * edge.z(), edge.x() * edge.x() + edge.z() * edge.z(),
                        edge.x() * edge.x() + edge.y() * edge.y());
  return Inertia(mass, Vector3::Zero(), (mass / 12.0 * moments).asDiagonal());
}

ContactGeometry ground_plane(const Matrix3& rotation = Matrix3::Identity()) {
  ContactGeometry plane;
  plane.name = "ground";
  plane.link = 0;
  plane.X_link_shape = Transform::from_rotation(rotation);
  plane.shape.kind = ContactShapeKind::plane;
  return plane;
}

/// A driver of `joint`'s coordinate: amplitude sin(omega t + phase), with its exact rates.
DriverDefinition sine_driver(std::string name, std::string joint, double amplitude, double omega, double phase = 0.0) {
  DriverDefinition driver;
  driver.name = std::move(name);
  driver.joint = std::move(joint);
  driver.motion = [=](double t) {
    const double s = std::sin(omega * t + phase), c = std::cos(omega * t + phase);
    return DriverMotion{amplitude * s, amplitude * omega * c, -amplitude * omega * omega * s};
  };
  return driver;
}

/// Sets body `body`'s free-joint coordinates (position, quaternion) in q.
void place(const Model& model, VectorX& q, const std::string& body, const Vector3& position,
           const Eigen::Quaterniond& orientation) {
  const int q_index = model.joints[model.link_index(body)].q_index;
  q.segment<3>(q_index) = position;
  q.segment<4>(q_index + 3) << orientation.w(), orientation.x(), orientation.y(), orientation.z();
}

ContactGeometry on_body(const Model& model, const std::string& body, const ContactShape& shape) {
  ContactGeometry geometry;
  geometry.name = body;
  geometry.link = model.link_index(body);
  geometry.shape = shape;
  return geometry;
}

/// One body on a free joint with its shape, over a ground plane turned by `turn` (the
/// body placed at `position` with the same turn), and the pair (body, plane).
ContactScene one_body_on_plane(const std::string& body, const Inertia& inertia, const ContactShape& shape,
                               const Eigen::Quaterniond& turn, const Vector3& position, double mu, double restitution) {
  ModelBuilder builder;
  builder.add_body({body, inertia, std::nullopt});
  builder.add_joint(joint_definition(body + "_free", JointKind::free, "ground", body));
  ContactScene scene;
  scene.model = std::make_shared<const Model>(builder.build());
  scene.masses = {inertia.mass()};
  scene.contacts.geometries = {ground_plane(turn.toRotationMatrix()), on_body(*scene.model, body, shape)};
  scene.contacts.pairs.push_back({body + "_on_ground", 1, 0, mu, restitution});
  scene.q = scene.model->neutral_configuration();
  scene.v = VectorX::Zero(scene.model->nv);
  place(*scene.model, scene.q, body, position, turn);
  return scene;
}

}  // namespace

ContactScene box_stack(int count, double edge, double bottom_mass, double mass_ratio, double mu) {
  ModelBuilder builder;
  ContactScene scene;
  const Vector3 half = Vector3::Constant(0.5 * edge);
  for (int i = 0; i < count; ++i) {
    const std::string name = "box" + std::to_string(i);
    const double mass = bottom_mass * (count > 1 ? std::pow(mass_ratio, double(i) / (count - 1)) : 1.0);
    scene.masses.push_back(mass);
    builder.add_body({name, solid_box(mass, half), std::nullopt});
    builder.add_joint(joint_definition(name + "_free", JointKind::free, "ground", name));
  }
  scene.model = std::make_shared<const Model>(builder.build());
  scene.contacts.geometries.push_back(ground_plane());
  scene.q = scene.model->neutral_configuration();
  scene.v = VectorX::Zero(scene.model->nv);
  for (int i = 0; i < count; ++i) {
    const std::string name = "box" + std::to_string(i);
    ContactShape box;
    box.kind = ContactShapeKind::box;
    box.half_extents = half;
    scene.contacts.geometries.push_back(on_body(*scene.model, name, box));
    // Below it: the ground (geometry 0) or the box before (geometry i).
    scene.contacts.pairs.push_back({name + "_below", i + 1, i, mu, 0.0});
    place(*scene.model, scene.q, name, Vector3(0, 0, edge * (i + 0.5)), Eigen::Quaterniond::Identity());
  }
  return scene;
}

ContactScene box_on_incline(double slope, double mu, const Vector3& half_extents, double mass) {
  const Eigen::Quaterniond tilt(Eigen::AngleAxisd(slope, Vector3::UnitY()));
  ContactShape box;
  box.kind = ContactShapeKind::box;
  box.half_extents = half_extents;
  return one_body_on_plane("box", solid_box(mass, half_extents), box, tilt, tilt * Vector3(0, 0, half_extents.z()),
                           mu, 0.0);
}

ContactScene sphere_on_plane(double radius, double mass, double height, double mu, double restitution) {
  ContactShape ball;
  ball.kind = ContactShapeKind::sphere;
  ball.radius = radius;
  return one_body_on_plane("ball", Inertia(mass, Vector3::Zero(), Matrix3::Identity() * (0.4 * mass * radius * radius)),
                           ball, Eigen::Quaterniond::Identity(), Vector3(0, 0, height), mu, restitution);
}

ContactScene box_on_moving_deck(const MovingDeck& deck, double mu, const Vector3& half_extents, double mass) {
  ModelBuilder builder;
  builder.add_body({"carriage", solid_box(1e3, Vector3(1, 1, 0.1)), std::nullopt});
  builder.add_body({"deck", solid_box(1e4, Vector3(5, 5, 0.1)), std::nullopt});
  builder.add_body({"box", solid_box(mass, half_extents), std::nullopt});
  builder.add_joint(joint_definition("surge", JointKind::prismatic, "ground", "carriage", Vector3::UnitX()));
  builder.add_joint(joint_definition("heave", JointKind::prismatic, "carriage", "deck", Vector3::UnitZ()));
  builder.add_joint(joint_definition("box_free", JointKind::free, "ground", "box"));
  const DriverDefinition surge = sine_driver("surge_motion", "surge", deck.surge_amplitude, deck.omega);
  const DriverDefinition heave = sine_driver("heave_motion", "heave", deck.heave_amplitude, deck.omega, deck.phase);
  builder.add_driver(surge);
  builder.add_driver(heave);
  ContactScene scene;
  scene.model = std::make_shared<const Model>(builder.build());
  scene.masses = {1e3, 1e4, mass};
  ContactGeometry top;  // the deck's top face as a plane in the deck's frame (origin on it)
  top.name = "deck";
  top.link = scene.model->link_index("deck");
  top.shape.kind = ContactShapeKind::plane;
  ContactShape box;
  box.kind = ContactShapeKind::box;
  box.half_extents = half_extents;
  scene.contacts.geometries = {top, on_body(*scene.model, "box", box)};
  scene.contacts.pairs.push_back({"box_on_deck", 1, 0, mu, 0.0});
  const Model& model = *scene.model;
  scene.q = model.neutral_configuration();
  scene.v = VectorX::Zero(model.nv);
  const DriverMotion x0 = surge.motion(0.0), z0 = heave.motion(0.0);
  scene.q[model.joints[model.joint_index("surge")].q_index] = x0.position;
  scene.q[model.joints[model.joint_index("heave")].q_index] = z0.position;
  scene.v[model.joints[model.joint_index("surge")].v_index] = x0.velocity;
  scene.v[model.joints[model.joint_index("heave")].v_index] = z0.velocity;
  place(model, scene.q, "box", Vector3(x0.position, 0.0, z0.position + half_extents.z()),
        Eigen::Quaterniond::Identity());
  const int box_v = model.joints[model.joint_index("box_free")].v_index;
  scene.v.segment<3>(box_v + 3) = Vector3(x0.velocity, 0.0, z0.velocity);
  return scene;
}

ContactScene standing_cylinder_on_plane(double radius, double half_length, double mass, double mu, double spin) {
  ContactShape cylinder;
  cylinder.kind = ContactShapeKind::cylinder;
  cylinder.radius = radius;
  cylinder.half_length = half_length;
  const double axial = 0.5 * mass * radius * radius;
  const double transverse = mass * (3.0 * radius * radius + 4.0 * half_length * half_length) / 12.0;
  ContactScene scene = one_body_on_plane("bit", Inertia(mass, Vector3::Zero(), Vector3(transverse, transverse, axial).asDiagonal()),
                                         cylinder, Eigen::Quaterniond::Identity(), Vector3(0, 0, half_length), mu, 0.0);
  scene.v[2] = spin;
  return scene;
}

ContactScene load_on_heaving_line(const HeavingTip& tip, double length, double mass, double restitution) {
  ModelBuilder builder;
  builder.add_body({"tip", solid_box(1e3, Vector3(0.5, 0.5, 0.5)), std::nullopt});
  builder.add_body({"load", solid_box(mass, Vector3(0.5, 0.5, 0.5)), std::nullopt});
  builder.add_joint(joint_definition("tip_heave", JointKind::prismatic, "ground", "tip", Vector3::UnitZ()));
  builder.add_joint(joint_definition("load_heave", JointKind::prismatic, "ground", "load", Vector3::UnitZ()));
  builder.add_driver(sine_driver("tip_motion", "tip_heave", tip.amplitude, tip.omega));
  ContactScene scene;
  scene.model = std::make_shared<const Model>(builder.build());
  scene.masses = {1e3, mass};
  const Model& model = *scene.model;
  scene.contacts.lines.push_back({"hoist_line", model.link_index("tip"), Vector3::Zero(), model.link_index("load"),
                                  Vector3::Zero(), length, restitution});
  scene.q = model.neutral_configuration();
  scene.v = VectorX::Zero(model.nv);
  const int tip_joint = model.joint_index("tip_heave"), load_joint = model.joint_index("load_heave");
  scene.v[model.joints[tip_joint].v_index] = tip.amplitude * tip.omega;
  scene.q[model.joints[load_joint].q_index] = -length;
  scene.v[model.joints[load_joint].v_index] = tip.amplitude * tip.omega;
  return scene;
}

StopScene load_on_heaving_floor(const HeavingTip& floor, double mass, double restitution, double drop) {
  ModelBuilder builder;
  builder.add_body({"floor", solid_box(1e4, Vector3(1, 1, 0.1)), std::nullopt});
  builder.add_body({"load", solid_box(mass, Vector3(0.5, 0.5, 0.5)), std::nullopt});
  builder.add_joint(joint_definition("floor_heave", JointKind::prismatic, "ground", "floor", Vector3::UnitZ()));
  builder.add_joint(joint_definition("lift", JointKind::prismatic, "floor", "load", Vector3::UnitZ()));
  builder.add_driver(sine_driver("floor_motion", "floor_heave", floor.amplitude, floor.omega));
  builder.add_joint_stop({"lift.lower", "lift", 0.0, true, restitution});
  StopScene scene;
  scene.model = std::make_shared<const Model>(builder.build());
  const Model& model = *scene.model;
  scene.q = model.neutral_configuration();
  scene.v = VectorX::Zero(model.nv);
  scene.v[model.joints[model.joint_index("floor_heave")].v_index] = floor.amplitude * floor.omega;
  scene.q[model.joints[model.joint_index("lift")].q_index] = drop;
  if (drop > 0.0) scene.v[model.joints[model.joint_index("lift")].v_index] = -floor.amplitude * floor.omega;  // at rest
  return scene;
}

}  // namespace heavesim::samples
