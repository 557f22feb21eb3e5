#include "kernel/model/data.hpp"

#include <atomic>
#include <stdexcept>
#include <string>

namespace heavesim {

Data::Data(const Model& model)
    : kkt_solver(model.num_constraint_rows) {
  const int n = model.num_links();
  q = model.neutral_configuration();
  // The position stage places revolute joints from Model::revolute_coordinates, which
  // ModelBuilder sets: a model assembled otherwise would leave its revolute joints unturned.
  std::vector<int> revolute;
  for (int i = 1; i < n; ++i)
    if (std::holds_alternative<RevoluteJoint>(model.joints[i].type)) revolute.push_back(model.joints[i].q_index);
  if (revolute != model.revolute_coordinates)
    throw std::logic_error("Data: Model::revolute_coordinates does not list the model's revolute joints "
                           "(build models with ModelBuilder)");
  revolute_cos = VectorX::Ones(model.nq);
  revolute_sin = VectorX::Zero(model.nq);
  v = VectorX::Zero(model.nv);
  X_world_link.assign(n, Transform::Identity());
  motion_subspace_world = Matrix6X::Zero(6, model.nv);
  rigid_inertia_world.assign(n, Inertia());
  added_inertia_world.assign(n, Matrix6::Zero());
  velocity_world.assign(n, Motion::Zero());
  bias_acceleration_world.assign(n, Motion::Zero());
  momentum_world.assign(n, Force::Zero());
  bias_force_world.assign(n, Force::Zero());
  qdd = VectorX::Zero(model.nv);
  acceleration_world.assign(n, Motion::Zero());
  joint_wrench_world.assign(n, Force::Zero());
  tau = VectorX::Zero(model.nv);
  composite_rigid_inertia_world.assign(n, InertiaAboutOrigin());
  composite_added_inertia_world.assign(n, Matrix6::Zero());
  composite_has_added_inertia.assign(n, 0);
  const int m = model.num_constraint_rows;
  constraint_residual = VectorX::Zero(m);
  constraint_velocity_target = VectorX::Zero(m);
  constraint_jacobian = MatrixX::Zero(m, model.nv);
  constraint_bias = VectorX::Zero(m);
  constraint_multipliers = VectorX::Zero(m);
  constraint_row_used = VectorX::Ones(m);
  constraint_active = VectorX::Ones(m);
  for (const Constraint& constraint : model.constraints)
    if (constraint.is_unilateral()) constraint_active.segment(constraint.first_row, constraint.rows.size()).setZero();
  kkt_minv_jt = MatrixX::Zero(model.nv, m);
  kkt_schur = MatrixX::Zero(m, m);
  kkt_rhs = VectorX::Zero(m);
  kkt_free_qdd = VectorX::Zero(model.nv);
  projection_step = VectorX::Zero(model.nv);
  projection_configuration = VectorX::Zero(model.nq);
  derivative_velocity.assign(n, Motion::Zero());
  derivative_acceleration.assign(n, Motion::Zero());
  derivative_force.assign(n, Force::Zero());
  articulated_inertia_world.assign(n, Matrix6::Zero());
  articulated_bias_world.assign(n, Force::Zero());
  aba_U = Matrix6X::Zero(6, model.nv);
  aba_D_inverse.resize(n);
  for (int i = 1; i < n; ++i) aba_D_inverse[i] = SmallMatrix::Zero(model.joints[i].nv, model.joints[i].nv);
  aba_u = VectorX::Zero(model.nv);
}

long StageMarker::fresh_evaluation_number() {
  // Ranges of 2^20 numbers: a thread goes back to the shared counter once per ~10^6
  // evaluations. A long does not run out (2^63 numbers).
  constexpr long range = 1L << 20;
  static std::atomic<long> next_range{0};
  thread_local long next = 0, end = 0;
  if (next == end) {
    next = next_range.fetch_add(range, std::memory_order_relaxed);
    end = next + range;
  }
  return ++next;  // 1 .. range in the first range: never 0
}

void require_stages(const Data& data, unsigned required, double t, long evaluation) {
  const StageMarker& stages = data.stages;
  if ((stages.current & required) == required && stages.evaluation == evaluation && stages.time == t) return;
  throw std::logic_error("stale multibody stages: wanted stages " + std::to_string(required) + " of evaluation " +
                         std::to_string(evaluation) + " at t = " + std::to_string(t) + " s, Data holds stages " +
                         std::to_string(stages.current) + " of evaluation " + std::to_string(stages.evaluation) +
                         " at t = " + std::to_string(stages.time) + " s");
}

}  // namespace heavesim
