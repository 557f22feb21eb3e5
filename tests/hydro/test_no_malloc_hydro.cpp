// No heap allocation in the hydro force elements' apply()/state_derivative()/outputs():
// compiled into heavesim_no_malloc_tests (EIGEN_RUNTIME_NO_MALLOC, see
// tests/kernel/no_malloc_config.hpp), on a free-floating box with every element.
#include <gtest/gtest.h>

#include "app/scene/recorded_load.hpp"
#include "hydro/elements/froude_krylov_force.hpp"
#include "hydro/elements/linear_body_loads.hpp"
#include "hydro/elements/nonlinear_hydrostatics.hpp"
#include "hydro/elements/radiation_convolution.hpp"
#include "hydro/elements/radiation_memory.hpp"
#include "hydro/elements/wave_excitation.hpp"
#include "hydro/waves/wave_spectrum.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/system/multibody_system.hpp"
#include "samples/floating_bodies.hpp"

namespace heavesim::hydro {
namespace {

/// A 200 t hull "hull" on a free joint, with the given added inertia (link frame).
std::shared_ptr<const Model> floating_hull(const std::optional<Matrix6>& added_inertia) {
  return samples::free_floating_body("hull", Inertia(2e5, Vector3(0, 0, -1), Vector3(1e6, 2e6, 3e6).asDiagonal()),
                                     added_inertia);
}

TEST(NoMallocHydro, ForceElementsDoNotAllocate) {
  auto model = floating_hull(Matrix6::Identity() * 1e5);
  const int link = model->link_index("hull");
  MultibodySystem system(model);
  system.add_force_element(std::make_unique<NonlinearHydrostatics>("buoyancy", link, box_mesh(Vector3(10, 8, 6), Vector3(0, 0, -1), 3)));
  system.add_force_element(std::make_unique<LinearRestoring>("mooring", link, Matrix6::Identity() * 1e4, Vector6::Zero(),
                                                             Transform::Identity()));
  Vector6 quadratic = Vector6::Constant(1e3);
  system.add_force_element(std::make_unique<BodyDamping>("drag", link, Matrix6::Identity() * 1e3, quadratic));
  ModePairStateSpace heave;
  heave.force_mode = heave.velocity_mode = 2;
  heave.A = StateMatrix::Identity(4, 4) * -0.5;
  heave.B = StateVector::Ones(4);
  heave.C = StateRowVector::Ones(4) * 1e4;
  ModePairStateSpace pitch_surge = heave;  // a dense A (heave's is diagonal): both products of state_derivative
  pitch_surge.force_mode = 4;
  pitch_surge.velocity_mode = 0;
  pitch_surge.A = StateMatrix::Constant(4, 4, 0.1) - StateMatrix::Identity(4, 4);
  system.add_force_element(std::make_unique<RadiationMemory>("radiation", link, std::vector{heave, pitch_surge}));
  RetardationKernel kernel{0.1, std::vector<Matrix6>(200, Matrix6::Identity() * 1e3)};
  system.add_force_element(std::make_unique<RadiationConvolution>("convolution", link, kernel));
  ExcitationData excitation;
  excitation.angular_frequencies = {0.3, 0.6, 1.2};
  excitation.headings = {0.0, M_PI / 2};
  excitation.force.assign(2, std::vector<ComplexVector6>(3, ComplexVector6::Constant({1e5, 2e4})));
  IrregularSeaSettings sea;
  sea.num_components = 50;
  sea.heading = 0.3;
  sea.ramp = Ramp{RampKind::cosine, 10.0};
  system.add_force_element(std::make_unique<FroudeKrylovForce>("froude_krylov", link, box_mesh(Vector3(10, 8, 6), Vector3(0, 0, -1), 2),
                                                               regular_wave(1.0, 7.0, 0.2)));
  auto waves = std::make_unique<WaveExcitation>("waves", link, excitation, irregular_sea(PiersonMoskowitz{2.0, 8.0}, sea));
  const WaveExcitation& wave_element = *waves;
  system.add_force_element(std::move(waves));
  VectorX q = model->neutral_configuration(), v = VectorX::Constant(model->nv, 0.1);
  q[2] = -0.5;
  VectorX y = system.initial_state(q, v), ydot(system.size());
  system.state_derivative(3.0, y, ydot);  // first use may size workspaces
  std::array<double, 2> values;
  Eigen::internal::set_is_malloc_allowed(false);
  EXPECT_NO_THROW(system.state_derivative(5.0, y, ydot));
  // Equal steps: the wave excitation keeps the step and then rotates its phasors.
  for (double t : {5.5, 6.0, 6.5, 7.0}) EXPECT_NO_THROW(system.state_derivative(t, y, ydot));
  EXPECT_NO_THROW(wave_element.outputs(5.0, *model, system.data(), VectorX(), values));
  Eigen::internal::set_is_malloc_allowed(true);
}

TEST(NoMallocHydro, RecordedLoadOutputsDoNotAllocate) {
  // The application's recording wrapper (app/scene/recorded_load.hpp) around a linear
  // restoring and a wave-excitation element: outputs() reads the load apply() kept at the
  // system's evaluation, and at another (a Data it never applied on) runs the wrapped
  // apply() into its own scratch forces.
  auto model = floating_hull(std::nullopt);
  const int link = model->link_index("hull");
  MultibodySystem system(model);
  ExcitationData excitation;
  excitation.angular_frequencies = {0.3, 0.6, 1.2};
  excitation.headings = {0.0, M_PI / 2};
  excitation.force.assign(2, std::vector<ComplexVector6>(3, ComplexVector6::Constant({1e5, 2e4})));
  auto sea = std::make_shared<const WaveTrain>(regular_wave(1.0, 7.0, 0.2));
  auto restoring = std::make_unique<RecordedLoad>(
      std::make_unique<LinearRestoring>("restoring", link, Matrix6::Identity() * 1e4, Vector6::Zero(), Transform::Identity()),
      *model, link, nullptr);
  auto waves = std::make_unique<RecordedLoad>(std::make_unique<WaveExcitation>("waves", link, excitation, *sea), *model,
                                              link, sea);
  const RecordedLoad& restoring_element = *restoring;
  const RecordedLoad& wave_element = *waves;
  ASSERT_EQ(restoring_element.channels().size(), 6u);
  ASSERT_EQ(wave_element.channels().size(), 2u + 6u + 1u);
  system.add_force_element(std::move(restoring));
  system.add_force_element(std::move(waves));
  VectorX q = model->neutral_configuration(), v = VectorX::Constant(model->nv, 0.1);
  q[2] = -0.5;
  VectorX y = system.initial_state(q, v), ydot(system.size());
  system.state_derivative(3.0, y, ydot);
  std::array<double, 6> restoring_values;
  std::array<double, 9> wave_values;
  std::array<double, 6> applied_again;
  Data other = system.data();
  VectorX q_other = q;
  q_other[0] += 0.01;  // moved 1 cm in x
  Eigen::internal::set_is_malloc_allowed(false);
  EXPECT_NO_THROW(system.state_derivative(5.0, y, ydot));
  EXPECT_NO_THROW(restoring_element.outputs(5.0, *model, system.data(), VectorX(), restoring_values));
  EXPECT_NO_THROW(wave_element.outputs(5.0, *model, system.data(), VectorX(), wave_values));
  EXPECT_NO_THROW({
    update_positions(*model, other, q_other);
    update_velocities(*model, other, q_other, v);
    other.stages.time = 5.0;
    restoring_element.outputs(5.0, *model, other, VectorX(), applied_again);
    wave_element.outputs(5.0, *model, other, VectorX(), wave_values);
  });
  Eigen::internal::set_is_malloc_allowed(true);
  EXPECT_NEAR(restoring_values[2], 1e4 * 0.5, 1e-6);  // F_z = -K xi_z, xi_z = -0.5 m
}

}  // namespace
}  // namespace heavesim::hydro
