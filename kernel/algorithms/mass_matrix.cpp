#include "kernel/algorithms/mass_matrix.hpp"

namespace heavesim {

// World form of the composite-rigid-body algorithm, one velocity coordinate at a time:
// with every S and composite inertia in world coordinates about the origin, the force
// F_c = Ic_i s_c that coordinate c of joint i needs is the same vector for every
// coordinate k on its path to the root (Model::velocity_coordinate_parent), so
// M(k, c) = s_k . F_c needs no transform
// (Featherstone 2008, table 6.2 with the transforms gone). Only the entries on those
// paths are written; the others are zero from the matrix's sizing at the first call and
// stay so.
// The rigid part of Ic adds as InertiaAboutOrigin (13 numbers); a 6x6 added part is
// carried only through subtrees that have one.
void size_mass_matrix(const Model& model, Data& data) {
  size_dense_matrix(data.mass_matrix, model.nv, model.nv);
  if (data.mass_matrix_cholesky.rows() != model.nv) data.mass_matrix_cholesky = SizedCholesky(model.nv);
}

const MatrixX& mass_matrix(const Model& model, Data& data) {
  const int n = model.num_links();
  const std::vector<int>& coordinate_parent = model.velocity_coordinate_parent;
  const Matrix6X& S = data.motion_subspace_world;
  size_mass_matrix(model, data);
  MatrixX& M = data.mass_matrix;
  auto& rigid = data.composite_rigid_inertia_world;
  auto& added = data.composite_added_inertia_world;
  auto& has_added = data.composite_has_added_inertia;
  for (int i = 1; i < n; ++i) {
    rigid[i].assign(data.rigid_inertia_world[i]);
    has_added[i] = model.links[i].added_inertia.has_value();
    if (has_added[i]) added[i] = data.added_inertia_world[i];
  }
  for (int i = n - 1; i >= 1; --i) {
    const Joint& joint = model.joints[i];
    const int parent = joint.parent;
    if (parent > 0) {
      rigid[parent] += rigid[i];
      if (has_added[i]) {
        if (has_added[parent]) added[parent] += added[i];
        else added[parent] = added[i];
        has_added[parent] = 1;
      }
    }
    for (int c = joint.v_index; c < joint.v_index + joint.nv; ++c) {
      Force F = rigid[i] * Motion(S.col(c));
      if (has_added[i]) F += added[i] * Motion(S.col(c));
      M(c, c) = dot(S.col(c), F);
      for (int k = coordinate_parent[c]; k >= 0; k = coordinate_parent[k]) M(c, k) = M(k, c) = dot(S.col(k), F);
    }
  }
  return M;
}

const MatrixX& crba(const Model& model, Data& data, const VectorX& q) {
  update_positions(model, data, q);
  return mass_matrix(model, data);
}

const Eigen::LLT<MatrixX>& factorize_mass_matrix(const Model& model, Data& data) {
  if (!(data.stages.current & StageMarker::mass_factor)) {
    data.mass_matrix_cholesky.compute(mass_matrix(model, data));
    data.stages.current |= StageMarker::mass_factor;
  }
  return data.mass_matrix_cholesky;
}

}  // namespace heavesim
