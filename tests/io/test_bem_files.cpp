// BEMIO HDF5 and Capytaine NetCDF4 files (io/bem/): the fixtures of tests/bem/, made
// from the MSS semi's WAMIT files by tests/bem/make_bem_fixtures.py (its own scalings,
// layouts and conjugation), read back equal to the WAMIT reader's dimensional data;
// the heave decay and regular-wave cases give the same history from either format;
// every malformed file of tests/bad_bem/ (bemio_*, capytaine_*) is bad input (exit
// code 2) naming the file, the dataset, what was found and what was expected; and the
// fuzzer's HDF5 findings (fuzz/regressions/fuzz_bemio, fuzz_capytaine).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <functional>

#include "io/bem/bem_file.hpp"
#include "io/bem/bemio_reader.hpp"
#include "io/bem/capytaine_reader.hpp"
#include "tests/app/h5_file.hpp"
#include "tests/test_support.hpp"

// A namespace of its own: the unity build compiles this file together with others
// (top CMakeLists.txt), whose file-local names must not meet these.
namespace heavesim::test_bem_files {
namespace {

constexpr double rho = 1025.0, g = 9.81;
const bem::WamitScaling scaling{rho, g, 1.0};
const std::string semisub = testing::source_path("data/mss_semisub/semisub");

/// Largest |a_ij - b_ij| / max|b|.
double relative_difference(const hydro::Matrix6& a, const hydro::Matrix6& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

struct Differences {
  double added_mass = 0, damping = 0, infinite = 0, zero = 0, magnitude = 0, phase = 0, stiffness = 0;
};

/// The file's radiation, excitation and stiffness against the WAMIT reader's, with the
/// largest differences (relative for A, B, C and |X|, radians for arg X).
Differences compare_with_wamit(const std::string& file, bool expect_zero_frequency) {
  SCOPED_TRACE(file);
  Differences d;
  const hydro::RadiationData wamit = bem::read_wamit_1(semisub + ".1", scaling);
  const hydro::RadiationData other = bem::read_radiation_file(file, scaling);
  EXPECT_EQ(other.angular_frequencies.size(), wamit.angular_frequencies.size());
  if (other.angular_frequencies.size() != wamit.angular_frequencies.size()) return d;
  for (std::size_t n = 0; n < wamit.angular_frequencies.size(); ++n) {
    EXPECT_NEAR(other.angular_frequencies[n], wamit.angular_frequencies[n], 1e-14);
    d.added_mass = std::max(d.added_mass, relative_difference(other.added_mass[n], wamit.added_mass[n]));
    d.damping = std::max(d.damping, relative_difference(other.damping[n], wamit.damping[n]));
  }
  d.infinite = relative_difference(other.added_mass_infinite, wamit.added_mass_infinite);
  EXPECT_EQ(other.has_added_mass_zero, expect_zero_frequency);
  if (expect_zero_frequency) d.zero = relative_difference(other.added_mass_zero, wamit.added_mass_zero);

  const hydro::ExcitationData wamit_x = bem::read_wamit_3(semisub + ".3", scaling);
  const hydro::ExcitationData other_x = bem::read_excitation_file(file, scaling);
  EXPECT_EQ(other_x.headings.size(), 4u);  // 0, 30, 90, 180 deg
  EXPECT_EQ(other_x.angular_frequencies, wamit_x.angular_frequencies);
  if (other_x.angular_frequencies.size() != wamit_x.angular_frequencies.size()) return d;
  int complex_entries = 0;  // entries whose phase is far from 0 and pi: conjugation shows
  for (std::size_t h = 0; h < other_x.headings.size(); ++h) {
    std::size_t hw = 0;
    while (hw < wamit_x.headings.size() && std::abs(wamit_x.headings[hw] - other_x.headings[h]) > 1e-12) ++hw;
    EXPECT_LT(hw, wamit_x.headings.size()) << "heading " << other_x.headings[h];
    if (hw == wamit_x.headings.size()) continue;
    for (std::size_t n = 0; n < wamit_x.angular_frequencies.size(); ++n) {
      const hydro::ComplexVector6& x = other_x.force[h][n];
      const hydro::ComplexVector6& reference = wamit_x.force[hw][n];
      const double largest = reference.cwiseAbs().maxCoeff();
      for (int i = 0; i < 6; ++i) {
        d.magnitude = std::max(d.magnitude, std::abs(std::abs(x[i]) - std::abs(reference[i])) / largest);
        if (std::abs(reference[i]) > 1e-6 * largest) {
          d.phase = std::max(d.phase, std::abs(std::arg(x[i] / reference[i])));
          if (std::abs(std::sin(std::arg(reference[i]))) > 0.5) ++complex_entries;
        }
      }
    }
  }
  EXPECT_GT(complex_entries, 100);
  d.stiffness = relative_difference(bem::read_hydrostatic_stiffness_file(file, scaling),
                                    bem::read_wamit_hst(semisub + ".hst", scaling));
  std::printf("%s: max relative difference A %.2e, B %.2e, A(inf) %.2e, A(0) %.2e, |X| %.2e, C %.2e; "
              "max phase difference %.2e rad\n",
              file.substr(file.find_last_of('/') + 1).c_str(), d.added_mass, d.damping, d.infinite, d.zero,
              d.magnitude, d.stiffness, d.phase);
  return d;
}

void expect_float_precision(const Differences& d) {
  for (double difference : {d.added_mass, d.damping, d.infinite, d.zero, d.magnitude, d.stiffness})
    EXPECT_LT(difference, 1e-13);
  EXPECT_LT(d.phase, 1e-12);
}

TEST(BemFiles, BemioCoefficientsEqualTheWamitReaders) {
  expect_float_precision(compare_with_wamit(testing::source_path("tests/bem/semisub.h5"), false));
  // The same data stored with every dimension reversed (MATLAB order, unpermuted).
  expect_float_precision(compare_with_wamit(testing::source_path("tests/bem/semisub_reversed_dims.h5"), false));
}

TEST(BemFiles, CapytaineCoefficientsEqualTheWamitReadersAfterConjugation) {
  expect_float_precision(compare_with_wamit(testing::source_path("tests/bem/semisub.nc"), true));
  // Other dimension orders and complex = [im, re]: found by name, not by position.
  expect_float_precision(compare_with_wamit(testing::source_path("tests/bem/semisub_transposed.nc"), true));
}

TEST(BemFiles, FormatFollowsTheExtension) {
  EXPECT_EQ(bem::bem_file_format("a/b.h5"), bem::BemFileFormat::bemio);
  EXPECT_EQ(bem::bem_file_format("a/b.HDF5"), bem::BemFileFormat::bemio);
  EXPECT_EQ(bem::bem_file_format("a/b.nc"), bem::BemFileFormat::capytaine);
  EXPECT_EQ(bem::bem_file_format("a.nc/b.1"), bem::BemFileFormat::wamit);
  EXPECT_EQ(bem::bem_file_format("b.hst"), bem::BemFileFormat::wamit);
}

/// `channel` of a run of `case_file` with `overrides`.
std::vector<double> run_channel(const std::string& case_file, const std::string& overrides, const std::string& name,
                                const std::string& channel) {
  const std::string output = temporary(name);
  const testing::CommandResult result = testing::run_command_line(
      testing::heavesim_binary() + " run -q " + testing::source_path(case_file) + " -o " + output + " " + overrides);
  EXPECT_EQ(result.exit_code, 0) << result.output;
  H5File file(output);
  return file.ok() ? file.read(channel) : std::vector<double>{};
}

double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double largest = a.size() == b.size() && !a.empty() ? 0.0 : INFINITY;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k) largest = std::max(largest, std::abs(a[k] - b[k]));
  return largest;
}

TEST(BemFiles, HeaveDecayIsTheSameFromWamitBemioAndCapytaineFiles) {
  const std::vector<double> wamit =
      run_channel("cases/hydro/heave_decay.yaml", "", "bem_decay_wamit.h5", "/joints/heave/q");
  ASSERT_GT(wamit.size(), 2000u);
  double amplitude = 0.0;
  for (double q : wamit) amplitude = std::max(amplitude, std::abs(q));
  EXPECT_NEAR(amplitude, 1.0, 1e-12);
  for (const char* format : {"bemio", "capytaine"}) {
    const std::vector<double> other = run_channel(std::string("cases/hydro/heave_decay_") + format + ".yaml", "",
                                                  std::string("bem_decay_") + format + ".h5", "/joints/heave/q");
    const double difference = largest_difference(other, wamit);
    std::printf("heave decay, %s file: largest |q - q_wamit| = %.3e m over %zu samples\n", format, difference,
                other.size());
    EXPECT_LT(difference, 1e-9) << format;
  }
}

TEST(BemFiles, RegularWaveResponseIsTheSameFromWamitBemioAndCapytaineFiles) {
  // Head seas (beta = pi, a heading the fixtures keep); excitation, radiation and
  // hydrostatics all from the one file. The conjugation of Capytaine's excitation
  // shows here as the phase of the heave response.
  const std::string shortened = "--set solver.t_end=120 --set output.evaluate_after=0";
  const std::vector<double> wamit =
      run_channel("cases/hydro/regular_wave.yaml", shortened, "bem_wave_wamit.h5", "/joints/heave/q");
  ASSERT_GT(wamit.size(), 1000u);
  for (const char* extension : {"h5", "nc"}) {
    const std::string file = testing::source_path(std::string("tests/bem/semisub.") + extension);
    const std::vector<double> other = run_channel(
        "cases/hydro/regular_wave.yaml",
        shortened + " --set forces[radiation].file=" + file + " --set forces[hydrostatics].hst=" + file +
            " --set forces[excitation].file=" + file,
        std::string("bem_wave_") + extension + ".h5", "/joints/heave/q");
    const double difference = largest_difference(other, wamit);
    std::printf("regular wave from semisub.%s: largest |q - q_wamit| = %.3e m\n", extension, difference);
    EXPECT_LT(difference, 1e-9) << extension;
  }
}

struct BadFile {
  const char* file;     // in tests/bad_bem/
  const char* element;  // the case element that reads it: radiation, hydrostatics, excitation
  const char* dataset;  // the dataset or variable named ("" when the file cannot be opened)
  const char* found;    // a piece of what the message says was found
};

// clang-format off
const BadFile bad_files[] = {
  {"bemio_not_hdf5.h5", "radiation", "", "not an HDF5 file"},
  {"bemio_truncated.h5", "radiation", "", "truncated or damaged"},
  {"bemio_missing_inf_freq.h5", "radiation", ":/body1/hydro_coeffs/added_mass/inf_freq", "no such dataset"},
  {"bemio_frequency_count_mismatch.h5", "radiation", ":/body1/hydro_coeffs/radiation_damping/all", "shape (6, 6, 7)"},
  {"bemio_nan_damping.h5", "radiation", ":/body1/hydro_coeffs/radiation_damping/all", "entry (3,3) at w = "},
  {"bemio_asymmetric_added_mass.h5", "radiation", ":/body1/hydro_coeffs/added_mass/all", "A(1,5) = "},
  {"bemio_scaled_flag_invalid.h5", "hydrostatics", ":/simulation_parameters/scaled", "scaled = 2"},
  {"bemio_wrong_units.h5", "radiation", ":/simulation_parameters/w", "units = 'Hz'"},
  {"bemio_missing_excitation_im.h5", "excitation", ":/body1/hydro_coeffs/excitation/im", "no such dataset"},
  {"bemio_only_zero_frequency.h5", "excitation", ":/simulation_parameters/w", "no frequency 0 < w < inf"},
  {"capytaine_not_netcdf.nc", "radiation", "", "not an HDF5 file"},
  {"capytaine_truncated.nc", "hydrostatics", "", "truncated or damaged"},
  {"capytaine_no_infinite_frequency.nc", "radiation", ":/omega", "no omega = inf entry"},
  {"capytaine_unknown_dof.nc", "radiation", ":/radiating_dof", "the dof 'Heaving' (entry 3)"},
  {"capytaine_nan_diffraction.nc", "excitation", ":/diffraction_force", "wave_direction = 0.523599, influenced_dof = Heave, re = nan"},
  {"capytaine_asymmetric_added_mass.nc", "radiation", ":/added_mass", "A(1,5) = "},
  {"capytaine_wrong_units.nc", "excitation", ":/wave_direction", "units = 'deg'"},
  {"capytaine_missing_radiation_damping.nc", "radiation", ":/radiation_damping", "no such dataset"},
  {"capytaine_wrong_shape.nc", "radiation", ":/radiation_damping", "shape (10, 6, 3) with dimensions"},
};
// clang-format on

TEST(BemFiles, EveryMalformedFileIsBadInputNamingFileDatasetFoundAndExpected) {
  int bemio = 0, capytaine = 0;
  for (const BadFile& bad : bad_files) {
    SCOPED_TRACE(bad.file);
    const std::string path = testing::source_path(std::string("tests/bad_bem/") + bad.file);
    const std::string element = bad.element;
    const std::string key = element == "hydrostatics" ? "hst" : "file";
    const std::string base = element == "excitation" ? "cases/hydro/regular_wave.yaml" : "cases/hydro/heave_decay.yaml";
    const testing::CommandResult result =
        testing::run_command_line(testing::heavesim_binary() + " check " + testing::source_path(base) + " --set forces[" +
                                  element + "]." + key + "=" + path);
    EXPECT_EQ(result.exit_code, 2) << result.output;
    // The case key, then the data file and its dataset in parentheses.
    EXPECT_NE(result.output.find("forces[" + element + "]." + key), std::string::npos) << result.output;
    EXPECT_NE(result.output.find(path + std::string(bad.dataset)), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("found "), std::string::npos) << result.output;
    EXPECT_NE(result.output.find(bad.found), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("; expected "), std::string::npos) << result.output;
    (bad.file[0] == 'b' ? bemio : capytaine) += 1;
  }
  EXPECT_GE(bemio, 5);
  EXPECT_GE(capytaine, 5);
}

TEST(BemFiles, EveryMalformedFixtureIsInTheTable) {
  int listed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(testing::source_path("tests/bad_bem"))) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("bemio_", 0) != 0 && name.rfind("capytaine_", 0) != 0) continue;
    ++listed;
    bool found = false;
    for (const BadFile& bad : bad_files) found = found || name == bad.file;
    EXPECT_TRUE(found) << name << " has no test";
  }
  EXPECT_EQ(listed, static_cast<int>(std::size(bad_files)));
}

// Stored values that are finite but not once made dimensional: BEMIO damping 1e306
// times rho w, and a Capytaine excitation whose diffraction and Froude-Krylov parts
// (1e308 each at omega = 0.785398, heading 0.523599, Heave) overflow when summed.
// Both used to be returned as inf.
TEST(BemFiles, CoefficientsThatOverflowOnceDimensionalAreBadData) {
  const std::string bemio = testing::source_path("fuzz/regressions/fuzz_bemio/damping_overflows_once_dimensional.bemio");
  const std::string capytaine = testing::source_path("fuzz/regressions/fuzz_capytaine/excitation_sum_overflows.nc");
  auto expect_overflow = [](const std::string& file, const std::string& says, const std::function<void()>& read) {
    try {
      read();
      ADD_FAILURE() << file << ": no error";
    } catch (const hydro::DataError& error) {
      EXPECT_EQ(error.file(), file) << error.what();
      EXPECT_NE(std::string(error.what()).find(says), std::string::npos) << error.what();
    }
  };
  expect_overflow(bemio + ":/body1/hydro_coeffs/radiation_damping/all",
                  "entry (3,3) at w = 0.785398 rad/s (frequency 5 of 8) = 1e+306, which overflows to inf once scaled",
                  [&] { bem::read_bemio_radiation(bemio, {rho, g}); });
  expect_overflow(capytaine + ":/diffraction_force + /Froude_Krylov_force",
                  "omega = 0.785398, wave_direction = 0.523599, influenced_dof = Heave, re of the sum = inf; expected",
                  [&] { bem::read_capytaine_excitation(capytaine, {rho, g}); });
}

}  // namespace
}  // namespace heavesim::test_bem_files
