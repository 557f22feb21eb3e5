#include "kernel/algorithms/inverse_dynamics_derivatives.hpp"

namespace heavesim {
namespace {

/// d(I m) for an inertia carried by a body that moves by the screw s: s x* (I m) - I (s x m).
HEAVESIM_INLINE Force moved_inertia_times(const Inertia& I, const Motion& s, const Motion& m) {
  return s.cross(I * m) - I * s.cross(m);
}
HEAVESIM_INLINE Force moved_inertia_times(const Matrix6& I, const Motion& s, const Motion& m) {
  return s.cross(I * m) - I * s.cross(m);
}

/// What a joint adds beyond moving its subtree rigidly (universal joints only): in
/// world coordinates, the change of its own subspace columns and of c_J.
struct OwnJointTerms {
  Motion subspace[6];      // dS_J[:, b] / d(coordinate) for each column b
  Motion bias_position;    // dc_J / dq[coordinate]
  Motion bias_velocity;    // dc_J / dv[coordinate]
};

OwnJointTerms own_joint_terms(const Data& data, const Joint& joint, int link, const VectorX& q, const VectorX& v,
                              int coordinate) {
  OwnJointTerms terms;
  std::visit(
      [&](const auto& type) {
        using J = std::decay_t<decltype(type)>;
        if constexpr (!J::has_constant_subspace) {
          const double* qj = q.data() + joint.q_index;
          const double* vj = v.data() + joint.v_index;
          const Transform& X = data.X_world_link[link];
          for (int b = 0; b < J::nv; ++b) terms.subspace[b] = X.act(type.subspace_derivative(qj, b, coordinate));
          terms.bias_position = X.act(type.bias_position_derivative(qj, vj, coordinate));
          terms.bias_velocity = X.act(type.bias_velocity_derivative(qj, vj, coordinate));
        }
      },
      joint.type);
  return terms;
}

bool constant_subspace(const JointType& type) {
  return std::visit([](const auto& j) { return std::decay_t<decltype(j)>::has_constant_subspace; }, type);
}

/// Sums each link's d f over its subtree (within [first, end)), in place.
void accumulate_subtree(const Model& model, Data& data, int first, int end) {
  for (int k = end - 1; k > first; --k) data.derivative_force[model.joints[k].parent] += data.derivative_force[k];
}

/// Column `column` of d tau: d tau_i for i in J's subtree (S_i^T dF_i, plus
/// (dS_i)^T F_i for configuration columns) and for J's ancestors (S_i^T dF_J).
void write_column(const Model& model, Data& data, int link, const Motion* screw, const OwnJointTerms* own,
                  MatrixX& out, int column) {
  out.col(column).setZero();
  for (int i = link; i < model.links[link].subtree_end; ++i) {
    const Joint& joint = model.joints[i];
    for (int r = 0; r < joint.nv; ++r) {
      const Motion S(data.motion_subspace_world.col(joint.v_index + r));
      double value = dot(S, data.derivative_force[i]);
      if (screw) {
        Motion dS = screw->cross(S);
        if (own && i == link) dS += own->subspace[r];
        value += dot(dS, data.joint_wrench_world[i]);
      }
      out(joint.v_index + r, column) = value;
    }
  }
  for (int i = model.joints[link].parent; i > 0; i = model.joints[i].parent) {
    const Joint& joint = model.joints[i];
    for (int r = 0; r < joint.nv; ++r)
      out(joint.v_index + r, column) =
          dot(data.motion_subspace_world.col(joint.v_index + r), data.derivative_force[link]);
  }
}

/// d f_k = d(I (a - a_g) + A a + v x* (I + A) v) for the link's motion changes dv, da
/// and (configuration columns) its rigid displacement by the screw s.
Force force_change(const Model& model, const Data& data, int k, const Motion* screw, const Motion& dv,
                   const Motion& da, const Motion& gravity_acceleration) {
  const Inertia& I = data.rigid_inertia_world[k];
  const Motion& v = data.velocity_world[k];
  const Motion& a = data.acceleration_world[k];
  Force df = I * da;
  Force momentum = I * v;
  Force dmomentum = I * dv;
  if (screw) {
    df += moved_inertia_times(I, *screw, a - gravity_acceleration);
    dmomentum += moved_inertia_times(I, *screw, v);
  }
  if (model.links[k].added_inertia) {
    const Matrix6& A = data.added_inertia_world[k];
    df += A * da;
    momentum += A * v;
    dmomentum += A * dv;
    if (screw) {
      df += moved_inertia_times(A, *screw, a);
      dmomentum += moved_inertia_times(A, *screw, v);
    }
  }
  return df + dv.cross(momentum) + v.cross(dmomentum);
}

}  // namespace

void inverse_dynamics_derivatives(const Model& model, Data& data, const VectorX& q, const VectorX& v,
                                  const VectorX& qdd, ExternalForces external_forces_world) {
  rnea(model, data, q, v, qdd, external_forces_world);
  size_dense_matrix(data.dtau_dq, model.nv, model.nv);
  size_dense_matrix(data.dtau_dv, model.nv, model.nv);
  const Motion gravity_acceleration(Vector3::Zero(), model.gravity);

  for (int j = 1; j < model.num_links(); ++j) {
    const Joint& joint = model.joints[j];
    if (joint.nv == 0) continue;
    const bool rigid = constant_subspace(joint.type);
    const int end = model.links[j].subtree_end;
    const Motion& v_p = data.velocity_world[joint.parent];
    const Motion& a_p = data.acceleration_world[joint.parent];
    const Motion& v_j = data.velocity_world[j];
    for (int c = 0; c < joint.nv; ++c) {
      const int column = joint.v_index + c;
      const Motion s(data.motion_subspace_world.col(column));
      const OwnJointTerms own = rigid ? OwnJointTerms{} : own_joint_terms(data, joint, j, q, v, c);

      // Configuration column: the subtree moves rigidly by s; a universal joint's own
      // subspace and bias change too (dv_extra, da_extra), felt by the whole subtree.
      Motion dv_extra = Motion::Zero(), da_extra = own.bias_position;
      for (int b = 0; b < joint.nv; ++b) {
        dv_extra += own.subspace[b] * v[joint.v_index + b];
        da_extra += own.subspace[b] * qdd[joint.v_index + b];
      }
      da_extra += v_p.cross(dv_extra);
      const Motion v_p_cross_s = v_p.cross(s);
      for (int k = j; k < end; ++k) {
        const Motion& v_k = data.velocity_world[k];
        const Motion dv = s.cross(v_k - v_p) + dv_extra;
        const Motion da = s.cross(data.acceleration_world[k] - a_p) + v_p_cross_s.cross(v_k - v_p) + da_extra +
                          dv_extra.cross(v_k - v_j);
        data.derivative_force[k] = force_change(model, data, k, &s, dv, da, gravity_acceleration);
      }
      accumulate_subtree(model, data, j, end);
      write_column(model, data, j, &s, rigid ? nullptr : &own, data.dtau_dq, column);

      // Velocity column.
      const Motion da_own = v_p_cross_s + own.bias_velocity;
      for (int k = j; k < end; ++k) {
        const Motion da = da_own + s.cross(data.velocity_world[k] - v_j);
        data.derivative_force[k] = force_change(model, data, k, nullptr, s, da, gravity_acceleration);
      }
      accumulate_subtree(model, data, j, end);
      write_column(model, data, j, nullptr, nullptr, data.dtau_dv, column);
    }
  }
}

}  // namespace heavesim
