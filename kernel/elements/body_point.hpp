#pragma once
// A point fixed on a body (or on ground), as force elements see it.
#include "kernel/model/data.hpp"

namespace heavesim {

struct BodyPoint {
  int link = 0;                      // model link index; 0 = ground
  Vector3 point_link = Vector3::Zero();  // m, in the link frame

  /// Resolves a point given in the user's body frame of `body_name`; throws
  /// std::out_of_range naming the body when there is none.
  static BodyPoint on_body(const Model& model, const std::string& body_name, const Vector3& point_body);

  Vector3 position_world(const Data& data) const { return data.X_world_link[link].act_point(point_link); }
  Vector3 velocity_world(const Data& data) const {
    return data.velocity_world[link].point_velocity(position_world(data));
  }
};

}  // namespace heavesim
