#include "kernel/model/model.hpp"

namespace heavesim {

int Model::link_index(const std::string& body_name) const {
  for (int i = 0; i < num_links(); ++i)
    if (links[i].name == body_name) return i;
  return -1;
}

int Model::joint_index(const std::string& joint_name) const {
  for (int i = 1; i < num_links(); ++i)
    if (joints[i].name == joint_name) return i;
  return -1;
}

bool Model::has_added_inertia() const {
  for (const Link& link : links)
    if (link.added_inertia) return true;
  return false;
}

double Model::total_mass() const {
  double mass = 0.0;
  for (const Link& link : links) mass += link.inertia.mass();
  return mass;
}

VectorX Model::neutral_configuration() const {
  VectorX q = VectorX::Zero(nq);
  for (int i = 1; i < num_links(); ++i)
    std::visit([&](const auto& joint) { joint.neutral(q.data() + joints[i].q_index); }, joints[i].type);
  return q;
}

}  // namespace heavesim
