#include "kernel/algorithms/articulated_body.hpp"

#include <limits>

#include <Eigen/Cholesky>

#include "kernel/math/positive_definite_inverse.hpp"

namespace heavesim {
namespace {

/// u - U^T a of a free joint (aba_u, aba_U of the backward pass) at its parent's
/// acceleration plus the joint's bias, a: D qdd equals it (Featherstone 2008, sec. 7.3).
Vector6 free_joint_residual(const Data& data, int v_index, const Motion& a) {
  return data.aba_u.segment<6>(v_index) - data.aba_U.middleCols<6>(v_index).transpose() * a.vector();
}

}  // namespace

const VectorX& articulated_body_forward_dynamics(const Model& model, Data& data, const VectorX& tau,
                                                 ExternalForces external_forces_world) {
  const int n = model.num_links();
  for (int i = 1; i < n; ++i) {
    data.articulated_inertia_world[i] = link_inertia_matrix(model, data, i);
    data.articulated_bias_world[i] = data.bias_force_world[i] - link_weight(model, data, i);
    if (!external_forces_world.empty()) data.articulated_bias_world[i] -= external_forces_world[i];
  }

  // Backward pass: project each subtree's articulated inertia through its joint.
  for (int i = n - 1; i >= 1; --i) {
    const Joint& joint = model.joints[i];
    Matrix6& IA = data.articulated_inertia_world[i];
    Force& pA = data.articulated_bias_world[i];
    const Motion& c = data.bias_acceleration_world[i];
    if (joint.nv == 1) {
      const Vector6 S = data.motion_subspace_world.col(joint.v_index);
      const Vector6 U = IA * S;
      const double D_inverse = 1.0 / S.dot(U);
      const double u = tau[joint.v_index] - dot(S, pA);
      data.aba_U.col(joint.v_index) = U;
      data.aba_D_inverse[i](0, 0) = D_inverse;
      data.aba_u[joint.v_index] = u;
      if (joint.parent > 0) {
        const Matrix6 Ia = IA - D_inverse * U * U.transpose();
        data.articulated_bias_world[joint.parent] += pA + Ia * c + Force(U * (D_inverse * u));
        data.articulated_inertia_world[joint.parent] += Ia;
      }
    } else if (joint.nv == 6) {
      // A free joint: the same in fixed-size 6 x 6 algebra (the dynamic-size path spent
      // ~10 % of a floating platform's run in Eigen's general LLT and triangular solves).
      const Matrix6 S = data.motion_subspace_world.middleCols<6>(joint.v_index);
      auto U = data.aba_U.middleCols<6>(joint.v_index);
      U.noalias() = IA * S;
      const Matrix6 D = S.transpose() * U;
      auto u = data.aba_u.segment<6>(joint.v_index);
      u.noalias() = tau.segment<6>(joint.v_index) - S.transpose() * pA.vector();
      if (joint.parent == 0) {
        // A floating base: its parent's acceleration (the world's) is known already, so
        // qdd = D^-1 (u - U^T (a_0 + c)) now, by a solve with D's Cholesky factor; the
        // forward pass takes it as it is. No parent needs U D^-1: forming D^-1 (most of
        // this joint's cost in a recorded sample's evaluation) is skipped.
        const Vector6 residual = free_joint_residual(data, joint.v_index, data.acceleration_world[0] + c);
        const Eigen::LLT<Matrix6> cholesky(D);
        data.qdd.segment<6>(joint.v_index) = cholesky.info() == Eigen::Success
                                                 ? Vector6(cholesky.solve(residual))
                                                 : Vector6::Constant(std::numeric_limits<double>::quiet_NaN());
      } else {
        const Matrix6 D_inverse = positive_definite_inverse<6>(D);
        data.aba_D_inverse[i] = D_inverse;
        const Matrix6 UD = U * D_inverse;
        const Matrix6 Ia = IA - UD * U.transpose();
        data.articulated_bias_world[joint.parent] += pA + Ia * c + Force(UD * u);
        data.articulated_inertia_world[joint.parent] += Ia;
      }
    } else if (joint.nv > 1) {
      const auto S = data.motion_subspace_world.middleCols(joint.v_index, joint.nv);
      auto U = data.aba_U.middleCols(joint.v_index, joint.nv);
      U.noalias() = IA * S;
      const SmallMatrix D = S.transpose() * U;
      data.aba_D_inverse[i] = D.llt().solve(SmallMatrix::Identity(joint.nv, joint.nv));
      auto u = data.aba_u.segment(joint.v_index, joint.nv);
      u.noalias() = tau.segment(joint.v_index, joint.nv) - S.transpose() * pA.vector();
      if (joint.parent > 0) {
        const Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 6> UD = U * data.aba_D_inverse[i];
        const Matrix6 Ia = IA - UD * U.transpose();
        data.articulated_bias_world[joint.parent] += pA + Ia * c + Force(UD * u);
        data.articulated_inertia_world[joint.parent] += Ia;
      }
    } else if (joint.parent > 0) {
      data.articulated_bias_world[joint.parent] += pA + IA * c;
      data.articulated_inertia_world[joint.parent] += IA;
    }
  }

  // Forward pass: accelerations from the root outwards.
  for (int i = 1; i < n; ++i) {
    const Joint& joint = model.joints[i];
    Motion a = data.acceleration_world[joint.parent] + data.bias_acceleration_world[i];
    if (joint.nv == 1) {
      const double qdd = data.aba_D_inverse[i](0, 0) *
                         (data.aba_u[joint.v_index] - dot(a, Force(data.aba_U.col(joint.v_index))));
      data.qdd[joint.v_index] = qdd;
      a += Motion(data.motion_subspace_world.col(joint.v_index) * qdd);
    } else if (joint.nv == 6) {
      if (joint.parent > 0)  // a floating base's qdd came from the backward pass
        data.qdd.segment<6>(joint.v_index) =
            Matrix6(data.aba_D_inverse[i]) * free_joint_residual(data, joint.v_index, a);
      a += Motion(data.motion_subspace_world.middleCols<6>(joint.v_index) * data.qdd.segment<6>(joint.v_index));
    } else if (joint.nv > 1) {
      const SmallVector residual = data.aba_u.segment(joint.v_index, joint.nv) -
                                   data.aba_U.middleCols(joint.v_index, joint.nv).transpose() * a.vector();
      auto qdd = data.qdd.segment(joint.v_index, joint.nv);
      qdd.noalias() = data.aba_D_inverse[i] * residual;
      a += Motion(data.motion_subspace_world.middleCols(joint.v_index, joint.nv) * qdd);
    }
    data.acceleration_world[i] = a;
  }
  data.stages.accelerations_computed();
  data.articulated_evaluation = data.stages.evaluation;
  return data.qdd;
}

bool articulated_body_joint_wrenches(const Model& model, Data& data) {
  if (!(data.stages.current & StageMarker::accelerations) || data.articulated_evaluation != data.stages.evaluation)
    return false;
  for (int i = 1; i < model.num_links(); ++i)
    data.joint_wrench_world[i] = data.articulated_inertia_world[i] * data.acceleration_world[i] +
                                 data.articulated_bias_world[i];
  data.stages.reactions_computed();
  return true;
}

const VectorX& aba(const Model& model, Data& data, const VectorX& q, const VectorX& v, const VectorX& tau,
                   ExternalForces external_forces_world) {
  update_positions(model, data, q);
  update_velocities(model, data, q, v);
  return articulated_body_forward_dynamics(model, data, tau, external_forces_world);
}

}  // namespace heavesim
