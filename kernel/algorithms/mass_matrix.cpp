#include "kernel/algorithms/mass_matrix.hpp"

namespace heavesim {

const MatrixX& mass_matrix(const Model& model, Data& data) {
  const int n = model.num_links();
  for (int i = 1; i < n; ++i) data.composite_inertia_world[i] = link_inertia_matrix(model, data, i);
  for (int i = n - 1; i >= 1; --i) {
    const Joint& joint = model.joints[i];
    if (joint.parent > 0) data.composite_inertia_world[joint.parent] += data.composite_inertia_world[i];
    if (joint.nv == 0) continue;
    const auto S_i = data.motion_subspace_world.middleCols(joint.v_index, joint.nv);
    // F = Ic_i S_i; M_ji = S_j^T F for i and every ancestor j.
    const Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 6> F = data.composite_inertia_world[i] * S_i;
    data.mass_matrix.block(joint.v_index, joint.v_index, joint.nv, joint.nv).noalias() = S_i.transpose() * F;
    for (int j = joint.parent; j > 0; j = model.joints[j].parent) {
      const Joint& ancestor = model.joints[j];
      if (ancestor.nv == 0) continue;
      auto block = data.mass_matrix.block(ancestor.v_index, joint.v_index, ancestor.nv, joint.nv);
      block.noalias() = data.motion_subspace_world.middleCols(ancestor.v_index, ancestor.nv).transpose() * F;
      data.mass_matrix.block(joint.v_index, ancestor.v_index, joint.nv, ancestor.nv) = block.transpose();
    }
  }
  return data.mass_matrix;
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
