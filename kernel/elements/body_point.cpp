#include "kernel/elements/body_point.hpp"

#include <stdexcept>

namespace heavesim {

BodyPoint BodyPoint::on_body(const Model& model, const std::string& body_name, const Vector3& point_body) {
  const int link = model.link_index(body_name);
  if (link < 0) throw std::out_of_range("no body named '" + body_name + "'");
  return {link, model.links[link].X_link_body.act_point(point_body)};
}

}  // namespace heavesim
