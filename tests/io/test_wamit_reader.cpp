// BEM readers: H7 (the MSS semi's WAMIT files against the numbers of
// docs/physics/hydrodynamics.md §12 and semisub.out, a Hulme hemisphere table written as a
// WAMIT .1 with ULEN = 5 m), the frequency-domain heave RAO against WAMIT's own .4,
// and one test per malformed file in tests/bad_bem/ (file and line in the message), and
// the fuzzer's WAMIT findings (fuzz/regressions/fuzz_wamit/).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

#include "hydro/analysis/frequency_domain_rao.hpp"
#include "hydro/hydrostatics/hull_mesh.hpp"
#include "io/bem/wamit_reader.hpp"
#include "tests/test_support.hpp"

// A namespace of its own: the unity build compiles this file together with others
// (top CMakeLists.txt), whose file-local names must not meet these.
namespace heavesim::hydro::test_wamit_reader {
namespace {

constexpr double rho = 1025.0, g = 9.81;
const std::string semisub = testing::source_path("data/mss_semisub/semisub");

TEST(HydroBem, H7SemisubCoefficientsMatchPublishedNumbers) {
  const BemData bem = bem::read_wamit(semisub, {rho, g, 1.0});
  const RadiationData& r = bem.radiation;
  ASSERT_EQ(r.angular_frequencies.size(), 29u);
  EXPECT_NEAR(r.angular_frequencies.front(), 2 * M_PI / 100.0, 1e-12);
  EXPECT_NEAR(r.angular_frequencies.back(), 2 * M_PI / 4.5, 1e-12);
  ASSERT_TRUE(r.has_added_mass_zero);
  // docs/physics/hydrodynamics.md §12: A33 = 6.65e7 kg (w -> 0), 5.93e7 kg (w -> inf).
  EXPECT_NEAR(r.added_mass_zero(2, 2), 6.486900e4 * rho, 1e-9 * 6.65e7);
  EXPECT_NEAR(r.added_mass_zero(2, 2), 6.65e7, 0.005e7);
  EXPECT_NEAR(r.added_mass_infinite(2, 2), 5.93e7, 0.005e7);
  // Mixed and rotational entries keep rho L^k with L = 1 and are symmetrised:
  // A24(0) = 6.054004e5 and A42(0) = 6.056959e5 in the file.
  EXPECT_NEAR(r.added_mass_zero(1, 3), rho * 0.5 * (6.054004e5 + 6.056959e5), 1e-6);
  EXPECT_EQ(r.added_mass_zero(1, 3), r.added_mass_zero(3, 1));
  // A33 at T = 8 s and 13-15 s is 7.1-7.2e7 kg; B = rho w B_bar (B33 = 2.09e7 N s/m
  // at 6.2 s: 1025 (2 pi / 6.2) B_bar with B_bar = 2.012e4 in the file).
  for (size_t n = 0; n < r.angular_frequencies.size(); ++n) {
    const double T = 2 * M_PI / r.angular_frequencies[n];
    if (T == 8.0 || (T >= 13.0 && T <= 15.0)) {
      EXPECT_GT(r.added_mass[n](2, 2), 7.09e7) << T;
      EXPECT_LT(r.added_mass[n](2, 2), 7.22e7) << T;
    }
    if (std::abs(T - 6.2) < 1e-9) {
      EXPECT_NEAR(r.damping[n](2, 2), 2.09e7, 0.01e7);
    }
  }
  for (int i = 0; i < 6; ++i) {  // radiation damping is not negative (beyond round-off)
    double largest = 0.0;
    for (const Matrix6& B : r.damping) largest = std::max(largest, B(i, i));
    for (const Matrix6& B : r.damping) EXPECT_GE(B(i, i), -1e-3 * largest) << "mode " << i + 1;
  }
  // C33 = 973.14 rho g = 9.785e6 N/m.
  EXPECT_NEAR(bem.hydrostatic_stiffness(2, 2), 973.1387 * rho * g, 1e-6);
  EXPECT_NEAR(bem.hydrostatic_stiffness(2, 2), 9.785e6, 0.0005e7);
  // Heave excitation, head seas: peak about 9.5e6 N/m near T = 12 s, cancellation
  // near T = 20 s (3.8e5 N/m).
  const ExcitationData& x = bem.excitation;
  ASSERT_EQ(x.headings.size(), 19u);
  EXPECT_EQ(x.headings.front(), 0.0);
  EXPECT_NEAR(x.headings.back(), M_PI, 1e-15);
  double peak = 0.0, peak_period = 0.0;
  for (size_t n = 0; n < x.angular_frequencies.size(); ++n) {
    const double magnitude = std::abs(x.force[0][n][2]);
    if (magnitude > peak) peak = magnitude, peak_period = 2 * M_PI / x.angular_frequencies[n];
    if (std::abs(2 * M_PI / x.angular_frequencies[n] - 20.0) < 1e-9) {
      EXPECT_NEAR(magnitude, 3.8e5, 0.1e5);
    }
  }
  EXPECT_NEAR(peak, 9.5e6, 0.1e6);
  EXPECT_NEAR(peak_period, 12.0, 1.5);
}

// The frequency-domain heave RAO from the coefficients we read,
//   xi3 = X3 / (C33 - w^2 (m + A33) + i w B33),
// against WAMIT's own RAO file semisub.4 (mass 5.19798e7 kg from semisub.frc; heave
// couples with nothing in head seas for this doubly symmetric hull).
TEST(HydroBem, H7HeaveRaoFromCoefficientsMatchesWamitRaoFile) {
  const BemData bem = bem::read_wamit(semisub, {rho, g, 1.0});
  const ExcitationData rao = bem::read_wamit_3(semisub + ".4", {1.0, 1.0, 1.0});  // nondimensional, heave: m/m
  const double mass = 51979800.0;
  ASSERT_EQ(rao.angular_frequencies.size(), bem.radiation.angular_frequencies.size());
  double worst = 0.0;
  for (size_t n = 0; n < rao.angular_frequencies.size(); ++n) {
    const double w = bem.radiation.angular_frequencies[n];
    const std::complex<double> impedance(bem.hydrostatic_stiffness(2, 2) - w * w * (mass + bem.radiation.added_mass[n](2, 2)),
                                         w * bem.radiation.damping[n](2, 2));
    const std::complex<double> xi = bem.excitation.force[0][n][2] / impedance;
    const std::complex<double> reference = rao.force[0][n][2];
    worst = std::max(worst, std::abs(xi - reference));
  }
  // Absolute [m/m]: 1.8e-3 at the 20 s cancellation (|xi| = 0.18), <= 6e-4 elsewhere,
  // where |xi| runs from 0.004 to 1.06.
  EXPECT_LT(worst, 2e-3);
  RecordProperty("worst_rao_difference", std::to_string(worst));
}

// All six modes, coupled, at every BEM frequency and the headings 0, 30, 90, 150 deg:
// the 6x6 frequency-domain solve with the .frc mass matrix and roll damping against
// WAMIT's .4 (translations in m/m; rotations nondimensionalised by a/L, i.e. rad/m
// with ULEN = 1). The difference is held to 1 % of each mode's largest RAO (measured
// 0.10 % surge ... 0.83 % yaw, whose RAO is small and only excited at 30 and 150 deg).
TEST(HydroBem, H7CoupledRaosMatchWamitRaoFile) {
  const BemData bem = bem::read_wamit(semisub, {rho, g, 1.0});
  const ExcitationData rao = bem::read_wamit_3(semisub + ".4", {1.0, 1.0, 1.0});
  RaoSettings settings;
  settings.mass << 51979800.0, 0, 0, 0, -25989900.0, 0,  //
      0, 51979800.0, 0, 25989900.0, 0, 0,                  //
      0, 0, 51979800.0, 0, 0, 0,                           //
      0, 25989900.0, 0, 56606002200.0, 0, 0,               //
      -25989900.0, 0, 0, 0, 60088648800.0, 0,              //
      0, 0, 0, 0, 0, 73096593750.0;                        // semisub.frc
  settings.external_damping(3, 3) = 2e9;
  double worst[6] = {0, 0, 0, 0, 0, 0}, largest[6] = {0, 0, 0, 0, 0, 0};
  for (size_t h : {0, 3, 9, 15})
    for (size_t n = 0; n < bem.radiation.angular_frequencies.size(); ++n) {
      const ComplexVector6 xi = frequency_domain_rao(bem, settings, n, h);
      for (int i = 0; i < 6; ++i) {
        worst[i] = std::max(worst[i], std::abs(xi[i] - rao.force[h][n][i]));
        largest[i] = std::max(largest[i], std::abs(rao.force[h][n][i]));
      }
    }
  for (int i = 0; i < 6; ++i) {
    RecordProperty("relative_mode_" + std::to_string(i + 1), std::to_string(worst[i] / largest[i]));
    EXPECT_LT(worst[i], 0.01 * largest[i]) << "mode " << i + 1;
  }
}

TEST(HydroBem, H7HulmeHemisphereTable) {
  const double a = 5.0, volume = 2.0 / 3.0 * M_PI * a * a * a;
  const RadiationData r = bem::read_wamit_1(testing::source_path("tests/bem/hulme_hemisphere.1"), {rho, g, a});
  // A(inf) is exactly half the displaced mass, A(0) = 0.831 of it.
  EXPECT_NEAR(r.added_mass_infinite(2, 2) / (rho * volume), 0.5, 5e-7);
  EXPECT_NEAR(r.added_mass_zero(2, 2) / (rho * volume), 0.831, 5e-7);
  const double ka[] = {0.1, 0.2, 0.4, 0.6, 1.0, 1.4, 2.0, 4.0, 10.0};
  const double A[] = {0.863, 0.794, 0.645, 0.538, 0.428, 0.392, 0.388, 0.432, 0.477};
  const double B[] = {0.182, 0.279, 0.341, 0.327, 0.248, 0.176, 0.103, 0.022, 0.001};
  ASSERT_EQ(r.angular_frequencies.size(), 9u);
  for (int n = 0; n < 9; ++n) {
    const double w = r.angular_frequencies[n];
    EXPECT_NEAR(w * w * a / g, ka[n], 1e-6 * ka[n]);  // deep water k a = w^2 a / g
    EXPECT_NEAR(r.added_mass[n](2, 2) / (rho * volume), A[n], 5e-7);
    EXPECT_NEAR(r.damping[n](2, 2) / (rho * w * volume), B[n], 5e-7);
  }
}

struct BadFile {
  const char* file;
  int line;
  const char* says;  // a phrase the message must contain
};

void expect_data_error(const std::string& path, int line, const std::string& says,
                       const std::function<void()>& read) {
  try {
    read();
    ADD_FAILURE() << path << ": no error";
  } catch (const DataError& e) {
    const std::string message = e.what();
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), line) << message;
    const std::string where = line > 0 ? path + ":" + std::to_string(line) + ": " : path + ": ";
    EXPECT_EQ(message.rfind(where, 0), 0u) << message;
    EXPECT_NE(message.find(says), std::string::npos) << message;
  }
}

TEST(HydroBem, BadRadiationFilesNameFileAndLine) {
  const BadFile files[] = {
      {"truncated_row.1", 3, "found 4 columns; expected 5 columns"},
      {"extra_column.1", 4, "found 6 columns"},
      {"nan_value.1", 3, "'NaN' in column 4; expected a finite number"},
      {"not_a_number.1", 3, "'1.0000x0E+03' in column 5; expected a number"},
      {"missing_infinite_frequency.1", 3, "no rows with PER = 0"},
      {"mode_out_of_range.1", 3, "J = 7"},
      {"negative_period.1", 3, "PER = -10"},
      {"duplicate_row.1", 4, "a second row for PER = 10, I = 3, J = 3"},
      {"mismatched_pairs.1", 5, "no row I = 1, J = 1 in the block PER = 5"},
      {"asymmetric_added_mass.1", 3, "A(1,5) = -8.2e+07 but A(5,1) = -4.1e+07"},
      {"infinite_row_with_damping.1", 2, "found 5 columns; expected 4 columns"},
      {"empty.1", 2, "no numeric rows"},
  };
  for (const BadFile& f : files) {
    const std::string path = testing::source_path(std::string("tests/bad_bem/") + f.file);
    expect_data_error(path, f.line, f.says, [&] { bem::read_wamit_1(path); });
  }
}

TEST(HydroBem, BadExcitationAndHydrostaticFilesNameFileAndLine) {
  const BadFile excitation[] = {
      {"wrong_columns.3", 2, "found 6 columns; expected 7 columns"},
      {"modulus_mismatch.3", 2, "|X| = 150 but sqrt(Re^2 + Im^2) = 100"},
      {"missing_heading.3", 2, "heading BETA = 90 deg at PER = 10"},
      {"duplicate_row.3", 2, "a second row for PER = 10, BETA = 0, I = 3"},
      {"zero_period.3", 2, "PER = 0"},
  };
  for (const BadFile& f : excitation) {
    const std::string path = testing::source_path(std::string("tests/bad_bem/") + f.file);
    expect_data_error(path, f.line, f.says, [&] { bem::read_wamit_3(path); });
  }
  const BadFile hydrostatic[] = {
      {"wrong_columns.hst", 2, "found 4 columns; expected 3 columns"},
      {"mode_zero.hst", 2, "J = 0"},
  };
  for (const BadFile& f : hydrostatic) {
    const std::string path = testing::source_path(std::string("tests/bad_bem/") + f.file);
    expect_data_error(path, f.line, f.says, [&] { bem::read_wamit_hst(path); });
  }
  const std::string base = testing::source_path("tests/bad_bem/frequency_mismatch");
  expect_data_error(base + ".3", 2, "period 6 s", [&] { bem::read_wamit(base); });
  expect_data_error(testing::source_path("tests/bad_bem/no_such_file.1"), 0, "a path that does not exist",
                    [&] { bem::read_wamit_1(testing::source_path("tests/bad_bem/no_such_file.1")); });
}

// Values the fuzzer found that are finite as written but not once made dimensional
// (rho w L^k B_bar, rho g L^k X_bar and C_bar) or whose frequency 2 pi / PER is not:
// they used to be returned as inf (a silent NaN later in the run).
TEST(HydroBem, ValuesThatOverflowOnceDimensionalNameFileAndLine) {
  const std::string dir = "fuzz/regressions/fuzz_wamit/";
  const bem::WamitScaling scaling{rho, g, 2.0};
  const std::string period = testing::source_path(dir + "period_whose_frequency_overflows.1");
  expect_data_error(period, 3, "PER = 1e-310, whose frequency 2 pi / PER overflows",
                    [&] { bem::read_wamit_1(period, scaling); });
  const std::string damping = testing::source_path(dir + "damping_overflows_once_dimensional.1");
  expect_data_error(damping, 2, "1e+308 in column 5, which overflows to inf",
                    [&] { bem::read_wamit_1(damping, scaling); });
  const std::string excitation = testing::source_path(dir + "excitation_overflows_once_dimensional.3");
  expect_data_error(excitation, 1, "1e+308 in column 6, which overflows to inf",
                    [&] { bem::read_wamit_3(excitation, scaling); });
  const std::string stiffness = testing::source_path(dir + "stiffness_overflows_once_dimensional.hst");
  expect_data_error(stiffness, 2, "1e+308 in column 3, which overflows to inf",
                    [&] { bem::read_wamit_hst(stiffness, scaling); });
}

TEST(HydroBem, ReadersRefuseWhatIsNotARegularFileBeforeOpeningIt) {
  // A FIFO's open() blocks until a writer comes; /dev/zero as text never ends; a
  // directory opens and reads as nothing. Each reader names what the path is instead
  // (hydro/data_file.hpp), whoever calls it.
  const std::filesystem::path directory =
      std::filesystem::temp_directory_path() / ("heavesim_data_paths_" + std::to_string(::getpid()));
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory / "folder");
  const std::string fifo = (directory / "pipe").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::vector<std::pair<std::string, std::string>> paths = {
      {fifo, "a named pipe (FIFO)"}, {"/dev/zero", "a character device"}, {(directory / "folder").string(), "a directory"}};
  for (const auto& [path, what] : paths) {
    for (const auto& read : std::vector<std::function<void()>>{
             [&path = path] { bem::read_wamit_1(path); }, [&path = path] { bem::read_wamit_hst(path); },
             [&path = path] { hydro::read_gdf(path); }, [&path = path] { hydro::read_stl(path); }}) {
      try {
        read();
        ADD_FAILURE() << path << " was read";
      } catch (const hydro::DataError& error) {
        EXPECT_EQ(error.file(), path);
        EXPECT_EQ(error.found(), what);
      }
    }
  }
  std::filesystem::remove_all(directory);
}

}  // namespace
}  // namespace heavesim::hydro::test_wamit_reader
