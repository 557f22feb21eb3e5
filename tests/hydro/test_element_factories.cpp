// The hydro element factories (hydro/elements/element_factories.hpp) against hand
// values: which radiation mode pairs are realised, the convolution's masking, the
// gravitational part taken out of a WAMIT .hst and the default buoyancy, and the
// ParameterErrors of settings that cannot be realised.
#include <gtest/gtest.h>

#include <cmath>

#include "hydro/elements/element_factories.hpp"
#include "hydro/radiation/state_space.hpp"
#include "kernel/parameter_error.hpp"

namespace heavesim::hydro {
namespace {

/// Three samples of a kernel with heave K33 = 4, pitch K55 = 9, surge K11 = 1 and the
/// couplings K35 = K53 (given) and K13 = K31 (given), at t = 0 only.
RetardationKernel hand_kernel(double heave_pitch, double surge_heave) {
  RetardationKernel kernel{0.1, std::vector<Matrix6>(3, Matrix6::Zero())};
  Matrix6& K = kernel.values[0];
  K(0, 0) = 1.0;
  K(2, 2) = -4.0;  // the largest magnitude counts, whatever its sign
  K(4, 4) = 9.0;
  K(2, 4) = K(4, 2) = heave_pitch;
  K(0, 2) = K(2, 0) = surge_heave;
  return kernel;
}

TEST(HydroElementFactories, RealisesThePairsNotNegligibleAgainstTheirDiagonal) {
  // Thresholds 1e-3 sqrt(K_ii K_jj): heave-pitch 1e-3 x 6 = 6e-3, surge-heave 2e-3.
  const ModeSet all = {true, true, true, true, true, true};
  using Pairs = std::vector<std::pair<int, int>>;
  EXPECT_EQ(realised_mode_pairs(hand_kernel(7e-3, 1e-3), all), (Pairs{{0, 0}, {2, 2}, {2, 4}, {4, 2}, {4, 4}}));
  EXPECT_EQ(realised_mode_pairs(hand_kernel(5e-3, 3e-3), all), (Pairs{{0, 0}, {0, 2}, {2, 0}, {2, 2}, {4, 4}}));
  // Only pairs of the modes asked for.
  const ModeSet heave = {false, false, true, false, false, false};
  EXPECT_EQ(realised_mode_pairs(hand_kernel(7e-3, 3e-3), heave), (Pairs{{2, 2}}));
}

/// 30 s of K33 = 5e5 e^(-0.2 t) cos(0.8 t) and K55 = 2e8 e^(-0.3 t) cos(1.1 t), every 0.05 s.
RetardationKernel damped_kernel() {
  RetardationKernel kernel{0.05, std::vector<Matrix6>(601, Matrix6::Zero())};
  for (std::size_t k = 0; k < kernel.values.size(); ++k) {
    const double t = 0.05 * static_cast<double>(k);
    kernel.values[k](2, 2) = 5e5 * std::exp(-0.2 * t) * std::cos(0.8 * t);
    kernel.values[k](4, 4) = 2e8 * std::exp(-0.3 * t) * std::cos(1.1 * t);
  }
  return kernel;
}

/// realize_memory's systems against realize_kernel_entry's, pair by pair, bit for bit.
void expect_realisations_of(const RetardationKernel& kernel, const ModeSet& modes, int order) {
  const std::vector<ModePairStateSpace> systems = realize_memory(kernel, modes, order);
  const auto pairs = realised_mode_pairs(kernel, modes);
  ASSERT_EQ(systems.size(), pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const ModePairStateSpace direct = realize_kernel_entry(kernel, pairs[k].first, pairs[k].second, order);
    EXPECT_EQ(Eigen::MatrixXd(systems[k].A), Eigen::MatrixXd(direct.A)) << "pair " << k << ", order " << order;
    EXPECT_EQ(Eigen::VectorXd(systems[k].B), Eigen::VectorXd(direct.B)) << "pair " << k << ", order " << order;
    EXPECT_EQ(Eigen::RowVectorXd(systems[k].C), Eigen::RowVectorXd(direct.C)) << "pair " << k << ", order " << order;
  }
}

// The process keeps its last realisations for a second build of the same scene: what it
// returns is always the realisation of the kernel, modes and order asked for, whichever
// was asked before (a kernel one sample apart, another order, other modes).
TEST(HydroElementFactories, RealisationsAreThoseOfTheKernelAsked) {
  const ModeSet heave_pitch = {false, false, true, false, true, false};
  const ModeSet heave = {false, false, true, false, false, false};
  const RetardationKernel kernel = damped_kernel();
  RetardationKernel changed = kernel;
  changed.values[300](2, 2) *= 1.01;
  for (int repeat = 0; repeat < 2; ++repeat) {  // the second time, every one is kept
    expect_realisations_of(kernel, heave_pitch, 4);
    expect_realisations_of(changed, heave_pitch, 4);
    expect_realisations_of(kernel, heave_pitch, 6);
    expect_realisations_of(kernel, heave, 4);
  }
  EXPECT_NE(Eigen::MatrixXd(realize_memory(kernel, heave, 4)[0].C),
            Eigen::MatrixXd(realize_memory(changed, heave, 4)[0].C));
}

TEST(HydroElementFactories, KeepModesZeroesEveryOtherPair) {
  RetardationKernel kernel = hand_kernel(7e-3, 3e-3);
  kernel.values[2] = kernel.values[0];
  keep_modes(kernel, {true, false, true, false, false, false});
  for (const Matrix6& K : {kernel.values[0], kernel.values[2]}) {
    EXPECT_EQ(K(0, 0), 1.0);
    EXPECT_EQ(K(2, 2), -4.0);
    EXPECT_EQ(K(0, 2), 3e-3);
    EXPECT_EQ(K(4, 4), 0.0);
    EXPECT_EQ(K(2, 4), 0.0);
    EXPECT_DOUBLE_EQ(K.cwiseAbs().sum(), 1.0 + 4.0 + 2 * 3e-3);
  }
}

TEST(HydroElementFactories, LinearHydrostaticsTakesWamitGravityOutAndDefaultsBuoyancyToWeight) {
  LinearHydrostaticsSettings s;
  s.stiffness = Matrix6::Identity() * 1e6;
  s.body_mass = 2.0e6;
  s.center_of_mass = Vector3(1.0, -2.0, -5.0);
  s.water_density = 1000.0;
  s.gravity = 10.0;
  EXPECT_EQ(restoring_stiffness(s), s.stiffness);
  // WAMIT's gravitational part: C44 = C55 = -m g z_G = 1e8, C46 = m g x_G = 2e7,
  // C56 = m g y_G = -4e7 (WAMIT User Manual v7, sec. 3.1), taken out.
  s.stiffness_includes_gravity = true;
  Matrix6 expected = s.stiffness;
  expected(3, 3) -= 1e8;
  expected(4, 4) -= 1e8;
  expected(3, 5) -= 2e7;
  expected(4, 5) -= -4e7;
  EXPECT_LE((restoring_stiffness(s) - expected).cwiseAbs().maxCoeff(), 1e-6);
  // Buoyancy: the weight m g = 2e7 N by default, rho g V with a displaced volume.
  Vector6 weight = Vector6::Zero();
  weight[2] = 2e7;
  EXPECT_EQ(buoyancy_load(s), weight);
  s.displaced_volume = 1500.0;
  EXPECT_EQ(buoyancy_load(s)[2], 1.5e7);
}

TEST(HydroElementFactories, SettingsThatCannotBeRealisedNameTheirField) {
  RadiationData radiation;
  radiation.angular_frequencies = {0.5, 1.0};
  radiation.damping = {Matrix6::Identity(), Matrix6::Identity()};
  radiation.added_mass = {Matrix6::Zero(), Matrix6::Zero()};
  auto field_of = [&](RadiationMemorySettings settings) -> std::string {
    try {
      radiation_memory("radiation", 1, radiation, settings);
    } catch (const ParameterError& error) {
      return error.field();
    }
    return "";
  };
  RadiationMemorySettings order_one;
  order_one.state_space_order = 1;
  EXPECT_EQ(field_of(order_one), "state_space_order");
  order_one.convolution = true;  // the order is checked for a convolution too
  EXPECT_EQ(field_of(order_one), "state_space_order");
  RadiationMemorySettings coarse;
  coarse.kernel_duration = 60.0;
  coarse.kernel_step = 7.0;  // fewer than ten samples
  EXPECT_EQ(field_of(coarse), "kernel_step");
  RadiationMemorySettings short_kernel;
  short_kernel.kernel_duration = 60.0;
  short_kernel.kernel_step = 3.0;  // 21 samples: a Hankel matrix of 10 < order 12
  EXPECT_EQ(field_of(short_kernel), "kernel_step");
}

}  // namespace
}  // namespace heavesim::hydro
