// Hydrodynamics through the application (cases/hydro/): the cases check; the free-heave
// decay of the MSS semi has the period 2 pi sqrt((m + A33(w_n)) / C33) computed here
// from the data files directly; the result file carries each hydro element's load and
// the wave elevation, against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "tests/app/h5_file.hpp"
#include "tests/test_support.hpp"
#include "validation/checks/harmonic_fit.hpp"

namespace heavesim {
namespace {

constexpr double rho = 1025.0, g = 9.81;

using testing::run_case;

/// Rows of whitespace-separated numbers of a text file (a small parser of its own, so the
/// reference does not go through hydro/bem).
std::vector<std::vector<double>> numeric_rows(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::vector<double> row;
    double value;
    while (words >> value) row.push_back(value);
    rows.push_back(row);
  }
  return rows;
}

TEST(HydroCases, EveryHydroCaseChecks) {
  for (const char* file : {"cases/hydro/heave_decay.yaml", "cases/hydro/regular_wave.yaml",
                           "cases/hydro/irregular_sea.yaml", "cases/hydro/heave_decay_nonlinear.yaml",
                           "cases/hydro/heave_decay_bemio.yaml", "cases/hydro/heave_decay_capytaine.yaml",
                           "cases/hydro/semisub_6dof_roll_decay.yaml",
                           "cases/hydro/semisub_6dof_pitch_decay.yaml", "cases/hydro/semisub_6dof_regular_wave.yaml",
                           "cases/hydro/semisub_6dof_irregular_sea.yaml"}) {
    const testing::CommandResult result =
        testing::check_case(file);
    EXPECT_EQ(result.exit_code, 0) << file << ": " << result.output;
  }
}

TEST(HydroCases, HeaveDecayPeriodMatchesMassAddedMassAndStiffnessFromTheFiles) {
  // m from semisub.frc (line 6, first entry of the mass matrix), C33 = rho g C33_bar from
  // semisub.hst, A33(w) = rho A33_bar(w) from semisub.1 (ULEN = 1), linearly interpolated
  // in period; the natural period solves T = 2 pi sqrt((m + A33(2 pi / T)) / C33).
  const auto frc = numeric_rows(testing::source_path("data/mss_semisub/semisub.frc"));
  const double mass = frc.at(5).at(0);  // line 6: first row of the mass matrix
  ASSERT_NEAR(mass, 51979800.0, 1.0);
  double c33 = 0.0;
  for (const auto& row : numeric_rows(testing::source_path("data/mss_semisub/semisub.hst")))
    if (row.size() == 3 && row[0] == 3 && row[1] == 3) c33 = rho * g * row[2];
  std::map<double, double> a33;  // period [s] -> A33 [kg]
  for (const auto& row : numeric_rows(testing::source_path("data/mss_semisub/semisub.1")))
    if (row.size() == 5 && row[1] == 3 && row[2] == 3 && row[0] > 0) a33[row[0]] = rho * row[3];
  ASSERT_GT(c33, 0.0);
  ASSERT_GE(a33.size(), 10u);
  auto added_mass = [&](double period) {
    auto upper = a33.lower_bound(period);
    if (upper == a33.begin()) return upper->second;
    if (upper == a33.end()) return std::prev(upper)->second;
    auto lower = std::prev(upper);
    return lower->second + (upper->second - lower->second) * (period - lower->first) / (upper->first - lower->first);
  };
  double period = 20.0;
  for (int k = 0; k < 100; ++k) period = 2 * M_PI * std::sqrt((mass + added_mass(period)) / c33);

  const std::string output = temporary("hydro_heave_decay.h5");
  const testing::CommandResult result = run_case("cases/hydro/heave_decay.yaml", output);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  H5File file(output);
  ASSERT_TRUE(file.ok());
  const std::vector<double> time = file.read("/time"), heave = file.read("/joints/heave/q");
  ASSERT_EQ(time.size(), heave.size());
  EXPECT_NEAR(heave.front(), 1.0, 1e-12);
  const double measured = validation::crossing_period(time, heave);
  std::printf("heave decay: measured T = %.4f s, reference 2 pi sqrt((m + A33(w_n))/C33) = %.4f s (A33(inf): %.4f s)\n",
              measured, period, 2 * M_PI * std::sqrt((mass + rho * 5.784468e4) / c33));
  EXPECT_NEAR(measured / period, 1.0, 0.005);
}

TEST(HydroCases, ResultFileCarriesHydroLoadsAndWaveElevation) {
  const std::string output = temporary("hydro_regular.h5");
  const testing::CommandResult result = run_case("cases/hydro/regular_wave.yaml", output, "--set solver.t_end=40 --set output.evaluate_after=20");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  H5File file(output);
  ASSERT_TRUE(file.ok());
  for (const char* element : {"hydrostatics", "radiation", "excitation", "viscous"})
    for (const char* channel : {"force_x", "force_y", "force_z", "moment_x", "moment_y", "moment_z"}) {
      const std::string path = std::string("/forces/") + element + "/" + channel;
      ASSERT_TRUE(file.exists(path)) << path;
      EXPECT_EQ(file.string_attribute(path, "units"), channel[0] == 'f' ? "N" : "N m") << path;
    }
  ASSERT_TRUE(file.exists("/forces/excitation/wave_elevation_at_body"));
  const std::vector<double> time = file.read("/time"), heave = file.read("/joints/heave/q"),
                            buoyancy = file.read("/forces/hydrostatics/force_z"),
                            eta = file.read("/forces/excitation/wave_elevation_at_body");
  // Linear hydrostatics: F_z = m g - C33 q, C33 = rho g 973.1387 m^2 (semisub.hst).
  // Wave at the origin in head seas: eta = R(t) a cos(w t), R the 30 s cosine ramp.
  const double mass = 51979800.0, c33 = rho * g * 973.1387, w = 2 * M_PI / 10.0;
  double buoyancy_error = 0.0, eta_error = 0.0;
  for (std::size_t k = 0; k < time.size(); ++k) {
    buoyancy_error = std::max(buoyancy_error, std::abs(buoyancy[k] - (mass * g - c33 * heave[k])));
    const double ramp = time[k] >= 30.0 ? 1.0 : 0.5 * (1 - std::cos(M_PI * time[k] / 30.0));
    eta_error = std::max(eta_error, std::abs(eta[k] - ramp * std::cos(w * time[k])));
  }
  EXPECT_LT(buoyancy_error, 1e-6 * mass * g);
  EXPECT_LT(eta_error, 1e-9);
  double largest_heave = 0.0;
  for (double q : heave) largest_heave = std::max(largest_heave, std::abs(q));
  EXPECT_GT(largest_heave, 1e-3);  // the wave moves the platform
}

TEST(HydroCases, NonlinearHydrostaticsRecordsBuoyancyOfTheClippedMesh) {
  // The recorded load is the element's own force (F_z = rho g V of the wetted hull at
  // that instant); at +1 m heave the volume is about V0 - A_wp * 1 m, with V0 = 50 709 m^3
  // and A_wp = 973.14 m^2 from semisub.out (the mesh is within 0.5 % of both, H2).
  const std::string output = temporary("hydro_nonlinear.h5");
  const testing::CommandResult result = run_case("cases/hydro/heave_decay_nonlinear.yaml", output,
                                            "--set solver.t_end=0.5 --set output.interval=0.05");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  H5File file(output);
  ASSERT_TRUE(file.ok());
  const std::vector<double> volume = file.read("/forces/hydrostatics/displaced_volume"),
                            force_z = file.read("/forces/hydrostatics/force_z"),
                            moment_x = file.read("/forces/hydrostatics/moment_x");
  ASSERT_FALSE(volume.empty());
  EXPECT_NEAR(volume.front() / (50709.0 - 973.14), 1.0, 0.01);
  for (std::size_t k = 0; k < volume.size(); ++k) {
    EXPECT_NEAR(force_z[k], rho * g * volume[k], 1e-9 * rho * g * volume[k]);
    EXPECT_LT(std::abs(moment_x[k]), 1e-6 * rho * g * volume[k]);  // port-starboard symmetric hull
  }
}

TEST(HydroCases, MooringAndDampingGiveTheDampedOscillator) {
  // m x'' + b x' + k x = 0, x(0) = 1, x'(0) = 0: x = e^{-zeta w t} (cos w_d t + zeta/sqrt(1-zeta^2) sin w_d t);
  // the recorded loads are -k x (mooring) and -b x' (damping), world x.
  const double m = 1.0e6, k = 4.0e5, b = 8.0e4, w = std::sqrt(k / m), zeta = b / (2 * std::sqrt(k * m)),
               wd = w * std::sqrt(1 - zeta * zeta);
  const std::string output = temporary("hydro_moored.h5");
  const testing::CommandResult result = run_case("tests/cases/moored_surge.yaml", output);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  H5File file(output);
  ASSERT_TRUE(file.ok());
  const std::vector<double> time = file.read("/time"), x = file.read("/joints/surge/q"),
                            xd = file.read("/joints/surge/qd"), mooring = file.read("/forces/mooring/force_x"),
                            damping = file.read("/forces/hull_damping/force_x"), drag = file.read("/forces/drag/force_x");
  double motion_error = 0.0, load_error = 0.0;
  for (std::size_t n = 0; n < time.size(); ++n) {
    const double t = time[n];
    const double exact = std::exp(-zeta * w * t) * (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t));
    motion_error = std::max(motion_error, std::abs(x[n] - exact));
    load_error = std::max({load_error, std::abs(mooring[n] + k * x[n]), std::abs(damping[n] + b * xd[n]), std::abs(drag[n])});
  }
  EXPECT_LT(motion_error, 1e-6);
  EXPECT_LT(load_error, 1e-6 * k);
}

}  // namespace
}  // namespace heavesim
