#include "app/scene/contact_scene.hpp"

#include <fmt/format.h>

#include "kernel/contact/contact_detection.hpp"

namespace heavesim {

void build_contacts(const CaseDefinition& definition, MultibodySystem& system) {
  const ContactDefinition& contacts = definition.contacts;
  if (contacts.empty()) return;
  const Model& model = system.model();
  ContactModel resolved;
  resolved.margin = contacts.margin;
  auto geometry_index = [&](const std::string& name) {
    for (std::size_t g = 0; g < contacts.geometries.size(); ++g)
      if (contacts.geometries[g].name == name) return static_cast<int>(g);
    return -1;  // the reader checked every name
  };
  for (const ContactGeometryDefinition& geometry : contacts.geometries) {
    ContactGeometry placed;
    placed.name = geometry.name;
    placed.link = model.link_index(geometry.body);
    // The user's body frame sits in the link frame by X_link_body.
    placed.X_link_shape = model.links[placed.link].X_link_body * geometry.X_body_shape;
    placed.shape = geometry.shape;
    resolved.geometries.push_back(placed);
  }
  for (const ContactPairDefinition& pair : contacts.pairs)
    resolved.pairs.push_back({pair.name, geometry_index(pair.geometry_a), geometry_index(pair.geometry_b),
                              pair.friction_coefficient, pair.restitution, pair.friction_directions,
                              pair.torsional_friction});
  for (const JointStopDefinition& stop : contacts.joint_stops)
    resolved.joint_stops.push_back({stop.name, model.joint_index(stop.joint), stop.lower, stop.upper, stop.restitution});
  for (const TensionLineDefinition& line : contacts.lines) {
    // Each end given in its body frame; the kernel takes it in the link frame.
    const int link_a = model.link_index(line.body_a), link_b = model.link_index(line.body_b);
    resolved.lines.push_back({line.name, link_a, model.links[link_a].X_link_body.act_point(line.point_a), link_b,
                              model.links[link_b].X_link_body.act_point(line.point_b), line.length,
                              line.restitution});
  }
  try {
    auto element = std::make_unique<ContactForces>("contacts", model, resolved);
    // Event-located stops (IDA): their forces are the multipliers of the model's stop rows.
    if (definition.solver.integrator.method == IntegrationMethod::ida) element->bind_stop_rows(model);
    system.set_contacts(std::move(element));
  } catch (const ParameterError& error) {
    throw to_input_error(definition, "contacts", error, {});
  }
  // A joint that starts beyond its stop: the first step would kick it back.
  for (std::size_t s = 0; s < resolved.joint_stops.size(); ++s) {
    const JointStop& stop = resolved.joint_stops[s];
    const double coordinate = system.data().q[model.joints[stop.joint].q_index];
    const bool below = coordinate < stop.lower - contacts.margin;
    if (below || coordinate > stop.upper + contacts.margin)
      throw definition.error_at(fmt::format("contacts.joint_stops[{}].{}", s, below ? "lower" : "upper"),
                                fmt::format("joint '{}' at {:.6g} at the initial state, beyond the stop at {:.6g}",
                                            contacts.joint_stops[s].joint, coordinate,
                                            below ? stop.lower : stop.upper),
                                "an initial coordinate within the stops (give the joint's `initial`, or move the stop)");
  }
  // Shapes that start inside each other by more than the margin: a modelling error (the
  // first step would throw them apart), refused before the run.
  std::vector<ContactPoint> points(max_contact_points(resolved));
  const int found = detect_contacts(model, system.data(), resolved, points);
  for (int k = 0; k < std::min(found, static_cast<int>(points.size())); ++k)
    if (points[k].gap < -contacts.margin) {
      const ContactPairDefinition& pair = contacts.pairs[points[k].pair];
      throw definition.error_at(fmt::format("contacts.pairs[{}].a", points[k].pair),
                                fmt::format("'{}' and '{}' overlapping by {:.4g} m at the initial state (at [{:.4g}, "
                                            "{:.4g}, {:.4g}] m, world)",
                                            pair.geometry_a, pair.geometry_b, -points[k].gap,
                                            points[k].point_world.x(), points[k].point_world.y(),
                                            points[k].point_world.z()),
                                fmt::format("an initial state where they touch or are apart (overlap <= "
                                            "contacts.margin = {:g} m): move a body or a shape frame",
                                            contacts.margin));
    }
}

}  // namespace heavesim
