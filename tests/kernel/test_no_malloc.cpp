// No heap allocation in the hot paths: the kernel is compiled for this test with
// EIGEN_RUNTIME_NO_MALLOC, and Eigen's allocation check throws (see
// no_malloc_config.hpp) if anything allocates while allocation is forbidden.
#include <gtest/gtest.h>

#include <random>

#include "kernel/algorithms/forward_dynamics.hpp"
#include "kernel/algorithms/joint_forces.hpp"
#include "kernel/algorithms/joint_reactions.hpp"
#include "kernel/system/multibody_system.hpp"
#include "validation/checks/random_models.hpp"

namespace heavesim {
namespace {

struct ForbidAllocation {
  ForbidAllocation() { Eigen::internal::set_is_malloc_allowed(false); }
  ~ForbidAllocation() { Eigen::internal::set_is_malloc_allowed(true); }
};

TEST(NoMalloc, AllocationCheckIsActive) {
  ForbidAllocation forbid;
  EXPECT_THROW({ VectorX v(100); (void)v; }, std::runtime_error);
}

TEST(NoMalloc, KernelAlgorithmsDoNotAllocate) {
  std::mt19937_64 random(3);
  validation::RandomTreeOptions options;
  options.bodies = 21;  // all seven joint types, three times
  options.added_inertia = true;
  const Model model = validation::random_tree(random, options);
  Data data(model);
  const validation::RandomState state = validation::random_state(model, random);
  VectorX tau = state.tau;
  {
    ForbidAllocation forbid;
    EXPECT_NO_THROW({
      update_positions(model, data, state.q);
      update_velocities(model, data, state.q, state.v);
      add_joint_element_forces(model, state.q, state.v, tau);
      inverse_dynamics(model, data, state.tau, state.external_forces);
      mass_matrix(model, data);
      articulated_body_forward_dynamics(model, data, tau, state.external_forces);
      composite_rigid_body_forward_dynamics(model, data, tau, state.external_forces);
      compute_joint_wrenches(model, data, state.external_forces);
      joint_reaction(model, data, 5);
    });
  }
}

TEST(NoMalloc, SystemDerivativeDoesNotAllocate) {
  std::mt19937_64 random(4);
  auto model = std::make_shared<const Model>(validation::random_tree(random, validation::RandomTreeOptions{}));
  for (ForwardDynamicsMethod method : {ForwardDynamicsMethod::articulated_body, ForwardDynamicsMethod::composite_rigid_body}) {
    SystemSettings settings;
    settings.method = method;
    MultibodySystem system(model, settings);
    const validation::RandomState state = validation::random_state(*model, random);
    VectorX y = system.initial_state(state.q, state.v), ydot(system.size());
    ForbidAllocation forbid;
    EXPECT_NO_THROW(system.derivative(0.0, y, ydot));
    EXPECT_NO_THROW(system.project(0.0, y));
  }
}

}  // namespace
}  // namespace heavesim
