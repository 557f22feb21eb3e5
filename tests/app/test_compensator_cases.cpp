// Compensators through the application: the rig cases load and run; the result file
// carries every element channel with units and description, and the compensator
// headlines; end-stop contacts counted by the summary agree with the recorded stroke;
// the C2 efficiencies of the passive and active H0 rigs against the linear
// transmissibility (passive) and docs/physics/drilling-rig.md §6's target (active).
#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "tests/app/h5_file.hpp"
#include "tests/test_support.hpp"

namespace heavesim {
namespace {

using testing::run_case;

double amplitude(const std::vector<double>& series, std::size_t from) {
  double low = 1e300, high = -1e300;
  for (std::size_t k = from; k < series.size(); ++k) low = std::min(low, series[k]), high = std::max(high, series[k]);
  return 0.5 * (high - low);
}

TEST(CompensatorCases, EveryRigCaseChecks) {
  for (const char* file : {"cases/c2_prescribed_heave/h0_locked.yaml", "cases/c2_prescribed_heave/h0_passive.yaml",
                           "cases/c2_prescribed_heave/h0_active.yaml",
                           "cases/c2_prescribed_heave/h0_active_hydraulic.yaml",
                           "cases/validation/c2_static_h0b.yaml", "cases/validation/c2_static_h0_elastic.yaml"}) {
    const testing::CommandResult result =
        testing::check_case(file);
    EXPECT_EQ(result.exit_code, 0) << file << ": " << result.output;
  }
}

TEST(CompensatorCases, ChannelsAndHeadlinesInTheResultFile) {
  const std::string output = temporary("c2_hydraulic.h5");
  const testing::CommandResult result =
      run_case("cases/c2_prescribed_heave/h0_active_hydraulic.yaml", output, "--set solver.t_end=20 --set solver.rtol=1e-6");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("compensator 'passive': stroke"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("compensator 'active': peak force"), std::string::npos) << result.output;
  H5File file(output);
  ASSERT_TRUE(file.ok());
  const std::vector<std::pair<std::string, std::string>> channels = {
      {"/forces/passive/gas_pressure", "Pa"}, {"/forces/passive/gas_temperature", "K"},
      {"/forces/passive/stroke", "m"},        {"/forces/passive/force", "N"},
      {"/forces/active/pressure_a", "Pa"},    {"/forces/active/supply_flow", "m^3/s"},
      {"/forces/active/supply_power", "W"},   {"/forces/active/valve_command", "-"},
      {"/forces/active/error", "m"},          {"/forces/active/saturated_command", "m/s"}};
  for (const auto& [path, units] : channels) {
    ASSERT_TRUE(file.exists(path)) << path;
    EXPECT_EQ(file.string_attribute(path, "units"), units) << path;
    EXPECT_FALSE(file.string_attribute(path, "description").empty()) << path;
  }
  for (const char* attribute : {"passive_stroke_max_m", "passive_end_stop_events_lower", "passive_gas_pressure_max_Pa",
                                "active_force_max_abs_N", "active_supply_energy_J"})
    EXPECT_TRUE(file.has_attribute("/summary", attribute)) << attribute;
  // The force channel is the gas spring's force on the moving side: at rest at t = 0 it
  // holds the 2.60 MN hook load (gas pressure from static balance).
  EXPECT_NEAR(file.read("/forces/passive/force")[0], 2.6006e6, 1e3);
  std::filesystem::remove(output);
}

TEST(CompensatorCases, EndStopContactsMatchTheRecordedStroke) {
  // Launched at 1.1 m/s the 290 t mass would swing about +-5.5 m: it hits both stops.
  const std::string output = temporary("c3_stops.h5");
  const testing::CommandResult result =
      run_case("cases/validation/c3_gas_spring.yaml", output, "--set joints[compensator].initial.qd=1.1");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  H5File file(output);
  const std::vector<double> stroke = file.read("/forces/passive/stroke");
  long lower = 0, upper = 0;
  for (std::size_t k = 1; k < stroke.size(); ++k) {
    lower += stroke[k] < -3.81 && stroke[k - 1] >= -3.81;
    upper += stroke[k] > 3.81 && stroke[k - 1] <= 3.81;
  }
  EXPECT_GT(lower, 0);
  EXPECT_GT(upper, 0);
  EXPECT_EQ(file.long_attribute("/summary", "passive_end_stop_events_lower"), lower);
  EXPECT_EQ(file.long_attribute("/summary", "passive_end_stop_events_upper"), upper);
  std::filesystem::remove(output);
}

TEST(CompensatorCases, PrescribedHeaveEfficiencyOfThePassiveAndActiveH0) {
  // Passive: the crown block's heave against k / (k - M w^2), k = n p0 A^2 / V0 with the
  // balance pressure for W_c = 2.60 MN on A = 0.1735 m^2 (M = 290 t, T = 10 s, 1 m).
  const double W = (30e3 + 25e3 + 45e3 + 190e3) * 9.81 - 1025.0 / 7850.0 * 190e3 * 9.81;
  const double p0 = 101325.0 + W / 0.1735, k = 1.4 * p0 * 0.1735 * 0.1735 / 60.0;
  const double w = 2 * M_PI / 10.0, expected = 1.0 - std::abs(k / (k - 290e3 * w * w));
  for (const char* mode : {"passive", "active"}) {
    const std::string output = temporary(std::string("c2_") + mode + ".h5");
    const testing::CommandResult result =
        run_case(std::string("cases/c2_prescribed_heave/h0_") + mode + ".yaml", output, "--set solver.t_end=100");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    H5File file(output);
    const std::vector<double> time = file.read("/time");
    const std::vector<double> crown_xyz = file.read("/bodies/crown/position"),
                              platform_xyz = file.read("/bodies/platform/position");
    std::vector<double> crown, platform;
    for (std::size_t k = 0; k < time.size(); ++k) {
      crown.push_back(crown_xyz[3 * k + 2]);
      platform.push_back(platform_xyz[3 * k + 2]);
    }
    const std::size_t from = time.size() / 2;  // the last 50 s, five periods
    const double efficiency = 1.0 - amplitude(crown, from) / amplitude(platform, from);
    if (std::string(mode) == "passive")
      EXPECT_NEAR(efficiency, expected, 0.005) << "linear transmissibility " << expected;  // 1 m: mildly nonlinear
    else
      EXPECT_GE(efficiency, 0.95) << "docs/physics/drilling-rig.md §6: passive + active >= 0.95";
    std::filesystem::remove(output);
  }
}

// The summary's efficiency 1 - sigma(z_load) / sigma(z_base) against the linear
// transmissibility of validation C1 (undamped gas spring, small heave, the load started
// on its forced response, so both heights are pure sinusoids at w: the sigma ratio is
// the amplitude ratio whatever the sampling). The window is set to whole periods.
TEST(CompensatorCases, SummaryEfficiencyMatchesTheLinearTransmissibility) {
  constexpr double M = 290000.0, A = 0.1735, V0 = 60.0, n = 1.4, p_atm = 101325.0, g = 9.81;
  const double k = n * (p_atm + M * g / A) * A * A / V0;
  for (double period : {8.0, 12.0}) {
    const std::string output = temporary(fmt::format("c1_efficiency_{:g}.h5", period));
    const testing::CommandResult result =
        run_case("cases/validation/c1_passive_compensator.yaml", output,
            fmt::format("--set parameters.T={:g} --set output.evaluate_after=0.3*T", period));
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("compensator 'passive': efficiency"), std::string::npos) << result.output;
    const double w = 2.0 * M_PI / period;
    const double expected = 1.0 - std::abs(k / (k - M * w * w));
    H5File file(output);
    ASSERT_TRUE(file.ok());
    EXPECT_NEAR(file.double_attribute("/summary", "passive_efficiency"), expected, 1e-4) << "T = " << period;
    EXPECT_NEAR(file.double_attribute("/summary", "passive_efficiency_window_start_s"), 0.3 * period, 1e-12);
  }
}

}  // namespace
}  // namespace heavesim
