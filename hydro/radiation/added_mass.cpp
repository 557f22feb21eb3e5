#include "hydro/radiation/added_mass.hpp"

namespace heavesim::hydro {

Matrix6 swap_linear_angular(const Matrix6& m) {
  Matrix6 s;
  s << m.bottomRightCorner<3, 3>(), m.bottomLeftCorner<3, 3>(), m.topRightCorner<3, 3>(), m.topLeftCorner<3, 3>();
  return s;
}

Matrix6 added_inertia_in_body_frame(const Matrix6& added_mass_wamit, const Vector3& r) {
  const Matrix6 symmetric = 0.5 * (added_mass_wamit + added_mass_wamit.transpose());
  // An inertia about the point r, moved to the body origin: the spatial-inertia
  // transform with X_body_reference = (1, r) (Featherstone eq. 2.66).
  return transform_spatial_inertia(Transform::from_translation(r), swap_linear_angular(symmetric));
}

}  // namespace heavesim::hydro
