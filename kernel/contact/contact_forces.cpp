#include "kernel/contact/contact_forces.hpp"

namespace heavesim {

ContactForces::ContactForces(std::string name, const Model& model, ContactModel contacts)
    : name_(std::move(name)),
      contacts_(std::move(contacts)),
      link_force_world_(model.num_links(), Force::Zero()),
      joint_force_(VectorX::Zero(model.nv)) {
  check_contact_model(model, contacts_);
  for (const ContactPair& pair : contacts_.pairs) {
    pair_channel_.push_back(static_cast<int>(channels_.size()));
    channels_.push_back({pair.name + "_normal_force", "N",
                         "sum of the normal forces of pair '" + pair.name +
                             "' on its first geometry, the last step's impulse / step (>= 0)"});
    channels_.push_back({pair.name + "_friction_force", "N",
                         "magnitude of the summed friction forces of pair '" + pair.name + "' (world)"});
    channels_.push_back({pair.name + "_points", "1", "contact points of pair '" + pair.name + "' in the last step"});
    if (pair.torsional_friction > 0.0)
      channels_.push_back({pair.name + "_torsion", "N m",
                           "moment of the torsional friction of pair '" + pair.name +
                               "' on its first geometry about the contact normal (the torque on a bit; > 0 "
                               "counterclockwise seen from the normal's tip)"});
  }
  first_stop_channel_ = static_cast<int>(channels_.size());
  for (const JointStop& stop : contacts_.joint_stops) {
    const Joint& joint = model.joints[stop.joint];
    stop_velocity_index_.push_back(joint.v_index);
    channels_.push_back({stop.name + "_force", std::holds_alternative<RevoluteJoint>(joint.type) ? "N m" : "N",
                         "generalized force of stop '" + stop.name + "' on joint '" + joint.name +
                             "' (> 0 along the coordinate), the last step's impulse / step"});
  }
  for (const TensionLine& line : contacts_.lines)
    channels_.push_back({line.name + "_tension", "N",
                         "tension of line '" + line.name + "' (>= 0; 0 while slack), the last step's impulse / step"});
  // Running totals: an impact lasts one step, between two samples; the difference of
  // two samples of a total is the impulse delivered between them, impacts included.
  for (const ContactPair& pair : contacts_.pairs) {
    impulse_channel_.push_back(static_cast<int>(channels_.size()));
    channels_.push_back({pair.name + "_normal_impulse", "N s",
                         "normal impulse of pair '" + pair.name + "' since the start (running total)"});
  }
  for (const JointStop& stop : contacts_.joint_stops) {
    impulse_channel_.push_back(static_cast<int>(channels_.size()));
    channels_.push_back({stop.name + "_impulse",
                         std::holds_alternative<RevoluteJoint>(model.joints[stop.joint].type) ? "N m s" : "N s",
                         "generalized impulse of stop '" + stop.name + "' since the start (running total, > 0 along "
                         "the coordinate)"});
  }
  for (const TensionLine& line : contacts_.lines) {
    impulse_channel_.push_back(static_cast<int>(channels_.size()));
    channels_.push_back({line.name + "_impulse", "N s",
                         "impulse of line '" + line.name + "' since the start (running total; a snap load is the "
                         "difference of two samples)"});
  }
  channel_values_ = VectorX::Zero(channels_.size());
  impulse_totals_ = VectorX::Zero(impulse_channel_.size());
  friction_sum_.assign(contacts_.pairs.size(), Vector3::Zero());
}

void ContactForces::apply(double, const Model&, const Data&, Eigen::Ref<const VectorX>, AppliedForces& forces) const {
  for (std::size_t i = 1; i < link_force_world_.size(); ++i) forces.external_force_world[i] += link_force_world_[i];
  forces.joint_force += joint_force_;
}

void ContactForces::outputs(double, const Model&, const Data& data, Eigen::Ref<const VectorX>,
                            std::span<double> values) const {
  for (std::size_t c = 0; c < values.size(); ++c) values[c] = channel_values_[c];
  // Event-located stops: the force is the multiplier of the active row (zero inactive).
  const std::size_t first_stop = first_stop_channel_;
  for (std::size_t s = 0; s < stop_rows_.size(); ++s) {
    double force = 0.0;
    for (const auto& [row, side] : stop_rows_[s]) force += side * data.constraint_active[row] * data.constraint_multipliers[row];
    values[first_stop + s] = force;
  }
}

void ContactForces::bind_stop_rows(const Model& model) {
  stop_rows_.assign(contacts_.joint_stops.size(), {});
  const std::size_t first_stop = first_stop_channel_;
  for (std::size_t s = 0; s < contacts_.joint_stops.size(); ++s) {
    const JointStop& stop = contacts_.joint_stops[s];
    channels_[first_stop + s].description = "generalized force of stop '" + stop.name + "' on joint '" +
                                            model.joints[stop.joint].name +
                                            "' (> 0 along the coordinate): the multiplier of its engaged bound";
    channels_[impulse_channel_[contacts_.pairs.size() + s]].description =
        "generalized impulse of the impacts on stop '" + stop.name +
        "' since the start (running total, > 0 along the coordinate; the force between impacts is <stop>_force)";
    for (const Constraint& constraint : model.constraints)
      if (const auto* row = std::get_if<JointStopConstraint>(&constraint.kind);
          row && row->joint == stop.joint && row->bound == (row->side > 0.0 ? stop.lower : stop.upper))
        stop_rows_[s].emplace_back(constraint.first_row, row->side);
  }
}

void ContactForces::add_stop_row_impulse(int row, double impulse) {
  for (std::size_t s = 0; s < stop_rows_.size(); ++s)
    for (const auto& [stop_row, side] : stop_rows_[s])
      if (stop_row == row) {
        const std::size_t total = contacts_.pairs.size() + s;
        impulse_totals_[total] += impulse;
        channel_values_[impulse_channel_[total]] = impulse_totals_[total];
      }
}

void ContactForces::clear() {
  for (Force& f : link_force_world_) f = Force::Zero();
  joint_force_.setZero();
  channel_values_.setZero();
  for (std::size_t k = 0; k < impulse_channel_.size(); ++k) channel_values_[impulse_channel_[k]] = impulse_totals_[k];
}

void ContactForces::set_from(const ContactStepper& stepper, double h) {
  clear();
  for (Vector3& sum : friction_sum_) sum.setZero();
  const auto points = stepper.contacts();
  for (int k = 0; k < static_cast<int>(points.size()); ++k) {
    const ContactPoint& c = points[k];
    const Vector3 force = stepper.contact_impulse_world(k) / h;
    const Force on_a = Force::at_point(c.point_world, force);
    link_force_world_[c.link_a] += on_a;
    link_force_world_[c.link_b] -= on_a;
    const double normal = force.dot(c.normal_world);
    const int first = pair_channel_[c.pair];
    channel_values_[first] += normal;
    friction_sum_[c.pair] += force - normal * c.normal_world;
    channel_values_[first + 2] += 1.0;
    if (contacts_.pairs[c.pair].torsional_friction > 0.0) {
      // A couple about the normal: the same on a as its opposite on b, wherever they are.
      const double torsion = stepper.contact_spin_impulse(k) / h;
      link_force_world_[c.link_a] += Force(torsion * c.normal_world, Vector3::Zero());
      link_force_world_[c.link_b] -= Force(torsion * c.normal_world, Vector3::Zero());
      channel_values_[first + 3] += torsion;
    }
  }
  link_force_world_[0] = Force::Zero();  // the ground takes what it takes
  for (std::size_t p = 0; p < friction_sum_.size(); ++p) channel_values_[pair_channel_[p] + 1] = friction_sum_[p].norm();
  const int first_stop = first_stop_channel_;
  for (std::size_t s = 0; s < stop_velocity_index_.size(); ++s) {
    const double force = stepper.stop_direction(static_cast<int>(s)) * stepper.stop_impulse(static_cast<int>(s)) / h;
    joint_force_[stop_velocity_index_[s]] += force;
    channel_values_[first_stop + s] = force;
    impulse_totals_[contacts_.pairs.size() + s] += force * h;
  }
  const std::size_t stops = stop_velocity_index_.size();
  for (std::size_t l = 0; l < contacts_.lines.size(); ++l) {
    const int line = static_cast<int>(l);
    const double tension = stepper.line_impulse(line) / h;
    if (tension != 0.0) {
      const Vector3 pull_on_a = tension * stepper.line_direction_world(line);
      link_force_world_[contacts_.lines[l].link_a] += Force::at_point(stepper.line_point_a_world(line), pull_on_a);
      link_force_world_[contacts_.lines[l].link_b] -= Force::at_point(stepper.line_point_b_world(line), pull_on_a);
    }
    channel_values_[first_stop + stops + l] = tension;
    impulse_totals_[contacts_.pairs.size() + stops + l] += tension * h;
  }
  link_force_world_[0] = Force::Zero();
  for (std::size_t p = 0; p < contacts_.pairs.size(); ++p) impulse_totals_[p] += channel_values_[pair_channel_[p]] * h;
  for (std::size_t k = 0; k < impulse_channel_.size(); ++k) channel_values_[impulse_channel_[k]] = impulse_totals_[k];
}

}  // namespace heavesim
