// The MSS semi free in six degrees of freedom (cases/hydro/semisub_6dof*.yaml) through
// the application path (case file -> scene -> integrator), against references solved
// here from the WAMIT files (semisub.1/.3/.hst read with hydro/bem, the mass matrix
// about the reference point taken from semisub.frc as WAMIT had it):
//  * still water at the reference pose stays there (all six coordinates);
//  * roll and pitch free decay: the period against the undamped eigenperiod of
//    [C + K_moor - w^2 (M + A(w))] x = 0 with A(w) interpolated in the BEM data;
//  * regular waves: the steady amplitudes and phases of all six motions (least-squares
//    fit), and one 3-hour irregular sea by cross-spectral (H1) estimation, against the
//    frequency-domain RAO
//      X = [-w^2 (M + A(w)) + i w (B(w) + B_visc) + C + K_moor]^-1 F(w, beta).
// C is semisub.hst as WAMIT wrote it (hydrostatic *and gravitational*, CG given): the
// run takes the gravity part out and lets the kernel apply the weight at the CoM, so a
// double count or a missing term shows here as a roll/pitch period or RAO error.
// Motions: xi = [position of the body origin (m); rotation vector of the body (rad)],
// world axes (small rotations: roll, pitch, yaw).
#include <gtest/gtest.h>

#include <cmath>
#include <array>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "app/run/simulation_run.hpp"
#include "app/scene/hydro_scene.hpp"
#include "app/scene/scene.hpp"
#include "hydro/excitation/excitation_interpolation.hpp"
#include "io/bem/wamit_reader.hpp"
#include "io/hdf5/hdf5_reader.hpp"
#include "signal/cross_spectrum.hpp"
#include "tests/test_support.hpp"
#include "validation/checks/harmonic_fit.hpp"

// A namespace of its own: the unity build compiles this file together with others
// (top CMakeLists.txt), whose file-local names must not meet these.
namespace heavesim::test_platform_6dof {
namespace {

using hydro::Matrix6;
using Vector6 = Eigen::Matrix<double, 6, 1>;
using ComplexMatrix6 = Eigen::Matrix<std::complex<double>, 6, 6>;
constexpr double rho = 1025.0, g = 9.81;

const hydro::BemData& semisub() {
  static const hydro::BemData bem = bem::read_wamit(testing::source_path("data/mss_semisub/semisub"), {rho, g, 1.0});
  return bem;
}

/// The 6x6 mass matrix about the reference point, WAMIT order, as semisub.frc gives it
/// (lines 6-11, after the title, the option flags, rho, the CG and a 1).
Matrix6 frc_mass_matrix() {
  std::ifstream in(testing::source_path("data/mss_semisub/semisub.frc"));
  std::string line;
  for (int skip = 0; skip < 5; ++skip) std::getline(in, line);
  Matrix6 M;
  for (int i = 0; i < 6; ++i) {
    std::getline(in, line);
    std::istringstream row(line);
    for (int j = 0; j < 6; ++j) row >> M(i, j);
  }
  return M;
}

/// The matrix of a hydro element of the loaded case (mooring stiffness, viscous damping).
Matrix6 case_matrix(const CaseDefinition& definition, const std::string& name) {
  for (const ForceDefinition& force : definition.forces) {
    if (force.name != name) continue;
    if (const auto* damping = std::get_if<LinearDampingDefinition>(&force.kind)) return damping->damping;
    if (const auto* mooring = std::get_if<MooringDefinition>(&force.kind)) return mooring->stiffness;
  }
  ADD_FAILURE() << "no force element " << name;
  return Matrix6::Zero();
}

/// A(w) and B(w), linear in w between the BEM frequencies (held beyond them).
std::pair<Matrix6, Matrix6> radiation_at(double w) {
  const hydro::RadiationData& r = semisub().radiation;
  const auto& f = r.angular_frequencies;
  if (w <= f.front()) return {r.added_mass.front(), r.damping.front()};
  if (w >= f.back()) return {r.added_mass.back(), r.damping.back()};
  const std::size_t n = std::upper_bound(f.begin(), f.end(), w) - f.begin();
  const double s = (w - f[n - 1]) / (f[n] - f[n - 1]);
  return {(1 - s) * r.added_mass[n - 1] + s * r.added_mass[n], (1 - s) * r.damping[n - 1] + s * r.damping[n]};
}

struct Record {
  std::vector<double> time;
  std::vector<Vector6> xi;  // [x, y, z; rotation vector], world axes
  double cpu_seconds = 0.0;
};

/// Runs a case file with overrides and records xi at every output time. The free
/// joint's q is [position; quaternion w, x, y, z] of the body frame in the world.
Record run_case(const std::string& file, const std::vector<std::string>& overrides = {}) {
  const CaseDefinition definition = load_case(testing::source_path(file), overrides);
  Scene scene = build_scene(definition);
  std::unique_ptr<Integrator> integrator = make_integrator(definition.solver.integrator, *scene.system);
  Record record;
  run_simulation(scene, definition.solver, definition.output.interval, *integrator, [&](double t, const VectorX& y) {
    const Eigen::AngleAxisd rotation(Eigen::Quaterniond(y[3], y[4], y[5], y[6]));
    Vector6 xi;
    xi << y.head<3>(), rotation.angle() * rotation.axis();
    record.time.push_back(t);
    record.xi.push_back(xi);
    return true;
  });
  return record;
}

CaseDefinition case_definition(const std::string& file) { return load_case(testing::source_path(file)); }

TEST(Platform6Dof, StillWaterStaysAtTheReferencePose) {
  // Weight at the CoM (0.5 m below the origin), buoyancy m g at the origin, no wave:
  // any stray force or moment (a misplaced buoyancy, a gravity term counted twice in
  // C at a nonzero angle, a memory or mooring offset) would move the platform.
  const Record record = run_case("cases/hydro/semisub_6dof.yaml",
                                 {"solver.integrator=rk4", "solver.step=0.05", "solver.t_end=600", "output.interval=1"});
  double largest = 0.0;
  for (const Vector6& xi : record.xi) largest = std::max(largest, xi.cwiseAbs().maxCoeff());
  EXPECT_LT(largest, 1e-9);
  RecordProperty("largest_displacement", std::to_string(largest));
}

/// The undamped eigenperiod nearest `guess` [s] of (C + K) x = w^2 (M + A(w)) x, A(w)
/// re-evaluated at each iterate until the period settles.
double eigenperiod(const Matrix6& stiffness, const Matrix6& mass, double guess) {
  double w = 2 * M_PI / guess;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const Matrix6 inertia = mass + radiation_at(w).first;
    Eigen::GeneralizedSelfAdjointEigenSolver<Matrix6> solver(0.5 * (stiffness + stiffness.transpose()),
                                                              0.5 * (inertia + inertia.transpose()));
    double nearest = 0.0;
    for (int k = 0; k < 6; ++k) {
      const double candidate = std::sqrt(std::max(solver.eigenvalues()[k], 0.0));
      if (std::abs(candidate - w) < std::abs(nearest - w)) nearest = candidate;
    }
    if (std::abs(nearest - w) < 1e-12 * w) break;
    w = nearest;
  }
  return 2 * M_PI / w;
}

// Roll (mode 4) and pitch (mode 5) decay from 2 deg, no viscous damping: the period of
// 4 cycles against the coupled eigenperiod (roll-sway and pitch-surge couple through
// m z_G and A24, A15; the single-mode formula is 2 % long for roll). Bar 0.5 %: the
// run's added mass at w_n comes from A(inf) plus the state-space memory realised from a
// 60 s kernel, which reproduces A(w) - A(inf) to about 1 % of A(w) near these periods,
// and the period goes with its square root. Measured (2026-11-23): roll -0.002 %, pitch
// +0.15 %. Counting the gravity part of semisub.hst twice (hst_includes_gravity: false)
// gives a roll period of 39.70 s, -4.2 %.
TEST(Platform6Dof, RollAndPitchDecayPeriodsMatchTheBemEigenperiods) {
  const Matrix6 mass = frc_mass_matrix();
  ASSERT_NEAR(mass(0, 0), 51979800.0, 1.0);
  ASSERT_NEAR(mass(0, 4), -25989900.0, 1.0);  // m z_G, z_G = -0.5 m
  const CaseDefinition definition = case_definition("cases/hydro/semisub_6dof_roll_decay.yaml");
  const Matrix6 stiffness = semisub().hydrostatic_stiffness + case_matrix(definition, "mooring");
  for (const auto& [file, mode] : {std::pair{"cases/hydro/semisub_6dof_roll_decay.yaml", 3},
                                   std::pair{"cases/hydro/semisub_6dof_pitch_decay.yaml", 4}}) {
    const double uncoupled_guess = 2 * M_PI * std::sqrt((mass(mode, mode) + radiation_at(0.15).first(mode, mode)) /
                                                        stiffness(mode, mode));
    const double reference = eigenperiod(stiffness, mass, uncoupled_guess);
    // The single-mode formula 2 pi sqrt((I + A(w_n)) / C), for the record.
    double uncoupled = uncoupled_guess;
    for (int k = 0; k < 100; ++k)
      uncoupled = 2 * M_PI *
                  std::sqrt((mass(mode, mode) + radiation_at(2 * M_PI / uncoupled).first(mode, mode)) / stiffness(mode, mode));
    const Record record = run_case(file);
    std::vector<double> angle;
    for (const Vector6& xi : record.xi) angle.push_back(xi[mode]);
    EXPECT_NEAR(angle.front(), 2 * M_PI / 180, 1e-12);
    // Four full cycles from the start (the 100 s mooring modes barely move the angle).
    std::vector<double> time_window, angle_window;
    for (std::size_t k = 0; k < record.time.size() && record.time[k] <= 4.2 * reference; ++k) {
      time_window.push_back(record.time[k]);
      angle_window.push_back(angle[k]);
    }
    const double measured = validation::crossing_period(time_window, angle_window);
    std::printf("%s decay: measured T = %.3f s, coupled eigenperiod %.3f s (error %.3f %%), single-mode "
                "2 pi sqrt((I + A(w_n))/C) = %.3f s\n",
                mode == 3 ? "roll" : "pitch", measured, reference, 100 * (measured / reference - 1), uncoupled);
    EXPECT_NEAR(measured / reference, 1.0, 0.005) << file;
    RecordProperty(mode == 3 ? "roll_period_error" : "pitch_period_error", std::to_string(measured / reference - 1));
  }
}

// Regular waves, a = 1 m, at BEM periods 8, 10, 12 and 15 s, heading 150 deg (every mode
// moves) and 180 deg (head seas: surge, heave, pitch). The last 5 wave periods of 800 s
// (100 s ramp; the slowest transient, the 5 %-damped 100 s mooring modes, has decayed by
// e^-(0.05 * 0.063 * 700) = 0.11 and sits far below the wave frequency, and the fit
// carries a constant term) fitted per mode against X above. Bars: modes whose RAO is at
// least 10 % of the largest of its kind (translations in m/m, rotations in rad/m against
// 1/20 rad/m) must agree to 3 % in amplitude and 3 deg in phase. What is not the same on
// both sides: the run's radiation is A(inf) + a 12-state realisation of a 60 s K(t),
// whose transfer function departs from WAMIT's A(w), B(w) by up to about 1 % of
// w^2 A(w) at these periods; the run is nonlinear in the rotations (second order at
// these amplitudes, < 1e-3). Measured (2026-11-23): at most 1.3 % (surge, 8 s, 150 deg)
// and 2.1 deg (pitch, 8 s, head seas, where its RAO is small and crosses over).
TEST(Platform6Dof, RegularWaveMotionsMatchTheFrequencyDomainRao) {
  const hydro::BemData& bem = semisub();
  const Matrix6 mass = frc_mass_matrix();
  const CaseDefinition definition = case_definition("cases/hydro/semisub_6dof_regular_wave.yaml");
  const Matrix6 stiffness = bem.hydrostatic_stiffness + case_matrix(definition, "mooring");
  const Matrix6 viscous = case_matrix(definition, "viscous");
  const std::complex<double> i(0.0, 1.0);
  double worst_amplitude = 0.0, worst_phase = 0.0;
  for (double heading_degrees : {150.0, 180.0}) {
    const auto& headings = bem.excitation.headings;
    const std::size_t h = std::min_element(headings.begin(), headings.end(), [&](double a, double b) {
                            return std::abs(a - heading_degrees * M_PI / 180) < std::abs(b - heading_degrees * M_PI / 180);
                          }) - headings.begin();
    ASSERT_NEAR(headings[h], heading_degrees * M_PI / 180, 1e-9);
    for (double period : {8.0, 10.0, 12.0, 15.0}) {
      const double w = 2 * M_PI / period;
      const auto& frequencies = bem.radiation.angular_frequencies;
      const std::size_t n = std::min_element(frequencies.begin(), frequencies.end(), [&](double a, double b) {
                              return std::abs(a - w) < std::abs(b - w);
                            }) - frequencies.begin();
      ASSERT_NEAR(frequencies[n], w, 1e-9);
      const ComplexMatrix6 impedance = (-w * w * (mass + bem.radiation.added_mass[n]) + stiffness).cast<std::complex<double>>() +
                                       i * w * (bem.radiation.damping[n] + viscous).cast<std::complex<double>>();
      const hydro::ComplexVector6 rao = impedance.partialPivLu().solve(bem.excitation.force[h][n]);
      const Record record = run_case("cases/hydro/semisub_6dof_regular_wave.yaml",
                                     {"parameters.period=" + std::to_string(period),
                                      "parameters.heading=deg(" + std::to_string(heading_degrees) + ")"});
      const double t_fit = record.time.back() - 5 * period;
      std::vector<double> times;
      for (double t : record.time)
        if (t >= t_fit) times.push_back(t);
      const double largest_translation = rao.head<3>().cwiseAbs().maxCoeff(), largest_rotation = rao.tail<3>().cwiseAbs().maxCoeff();
      for (int mode = 0; mode < 6; ++mode) {
        std::vector<double> x;
        for (std::size_t k = record.time.size() - times.size(); k < record.time.size(); ++k) x.push_back(record.xi[k][mode]);
        const std::complex<double> measured = validation::fit_harmonic(times, x, w);
        const double scale = mode < 3 ? std::max(largest_translation, 0.05) : std::max(largest_rotation, 0.05 / 20);
        const double amplitude_error = std::abs(std::abs(measured) / std::abs(rao[mode]) - 1.0);
        const double phase_error = std::abs(std::arg(measured / rao[mode])) * 180 / M_PI;
        std::printf("beta %3.0f T %4.1f mode %d: |X| run %.4e  RAO %.4e  amplitude error %6.2f %%  phase error %6.2f deg%s\n",
                    heading_degrees, period, mode + 1, std::abs(measured), std::abs(rao[mode]), 100 * amplitude_error,
                    phase_error, std::abs(rao[mode]) >= 0.1 * scale ? "" : "  (small, not checked)");
        if (std::abs(rao[mode]) < 0.1 * scale) continue;
        EXPECT_LT(amplitude_error, 0.03) << "beta " << heading_degrees << " T " << period << " mode " << mode + 1;
        EXPECT_LT(phase_error, 3.0) << "beta " << heading_degrees << " T " << period << " mode " << mode + 1;
        worst_amplitude = std::max(worst_amplitude, amplitude_error);
        worst_phase = std::max(worst_phase, phase_error);
      }
    }
  }
  RecordProperty("amplitude_error", std::to_string(worst_amplitude));
  RecordProperty("phase_error_deg", std::to_string(worst_phase));
}

// The same RAO from one irregular run: cases/hydro/semisub_6dof_irregular_sea.yaml (JONSWAP
// Hs = 4 m, Tp = 10 s, head seas, 3 hours, output every 0.5 s) with 1000 equal-energy
// components instead of its 200. Input: the undisturbed elevation at the reference
// point's mean position (the origin, to which the BEM excitation phases refer), from the
// case's own wave train; outputs: surge, heave, pitch. H1 = G_xy / G_xx over 2048-sample
// (1024 s) half-overlapping Hann segments from t = 200 s (ramp and start-up transients
// gone): 19 segments, df = 0.98 mHz. Compared at every bin where the coherence exceeds 0.9,
// the sea holds energy (G_xx >= 1 % of its peak) and the RAO matters (|X| >= 10 % of the
// mode's largest over those bins, as the regular-wave test's rule), against
// X(w) = Z(w)^-1 F(w, 180 deg) with A(w), B(w) and F linear in w between the BEM points.
// Bars as the regular-wave test's, 3 % and 3 deg: beyond the run's radiation realisation
// (about 1 % of w^2 A) come the estimator's random error, sqrt(1 - g^2) / (|g| sqrt(2 n_d))
// (Bendat & Piersol 2010, Table 9.6; < 0.2 % at the coherences met here, > 0.999), and
// the bin-to-component offset: a bin between two wave components reads the RAO where
// they are, not where it is. With 200 components they are 2-4 mHz apart at 7 s, and on
// the steep flank of the surge RAO (7.6 per Hz) that alone is 6 %; with 1000 they are
// closer than the window's main lobe. Measured (2026-11-25): surge 2.9 % and 1.5 deg,
// heave 1.4 % and 1.2 deg, pitch 2.8 % and 1.5 deg, at 74-106 bins each.
TEST(Platform6Dof, IrregularSeaH1RaoMatchesTheFrequencyDomainRao) {
  const hydro::BemData& bem = semisub();
  const Matrix6 mass = frc_mass_matrix();
  const std::string file = "cases/hydro/semisub_6dof_irregular_sea.yaml";
  const std::vector<std::string> overrides = {"waves.components=1000"};
  const CaseDefinition definition = load_case(testing::source_path(file), overrides);
  const Matrix6 stiffness = bem.hydrostatic_stiffness + case_matrix(definition, "mooring");
  const Matrix6 viscous = case_matrix(definition, "viscous");
  const hydro::WaveTrain waves = wave_train(definition);
  const Record record = run_case(file, overrides);
  const double dt = record.time[1] - record.time[0], t_start = 200.0;
  std::vector<double> elevation;
  std::array<std::vector<double>, 6> motion;
  for (std::size_t k = 0; k < record.time.size(); ++k) {
    if (record.time[k] < t_start) continue;
    elevation.push_back(waves.elevation(record.time[k], 0.0, 0.0));
    for (int mode = 0; mode < 6; ++mode) motion[mode].push_back(record.xi[k][mode]);
  }
  const std::complex<double> i(0.0, 1.0);
  const char* names[6] = {"surge", "sway", "heave", "roll", "pitch", "yaw"};
  for (int mode : {0, 2, 4}) {
    const stats::CrossSpectralEstimate e = stats::cross_spectral_density(elevation, motion[mode], 2048, 1.0 / dt);
    const double peak_input = *std::max_element(e.input_density.begin(), e.input_density.end());
    struct Bin {
      double period;
      std::complex<double> estimate, rao;
    };
    std::vector<Bin> bins;
    double largest = 0.0;
    for (std::size_t k = 1; k < e.frequencies.size(); ++k) {
      if (!(e.coherence(k) > 0.9) || e.input_density[k] < 0.01 * peak_input) continue;
      const double w = 2 * M_PI * e.frequencies[k];
      const auto [added_mass, damping] = radiation_at(w);
      const ComplexMatrix6 impedance = (-w * w * (mass + added_mass) + stiffness).cast<std::complex<double>>() +
                                       i * w * (damping + viscous).cast<std::complex<double>>();
      const hydro::ComplexVector6 rao =
          impedance.partialPivLu().solve(hydro::interpolate_excitation(bem.excitation, w, M_PI));
      bins.push_back({1.0 / e.frequencies[k], e.transfer_function(k), rao[mode]});
      largest = std::max(largest, std::abs(rao[mode]));
    }
    double worst_amplitude = 0.0, worst_phase = 0.0;
    int compared = 0;
    for (const Bin& bin : bins) {
      if (std::abs(bin.rao) < 0.1 * largest) continue;
      const double amplitude_error = std::abs(std::abs(bin.estimate) / std::abs(bin.rao) - 1.0);
      const double phase_error = std::abs(std::arg(bin.estimate / bin.rao)) * 180 / M_PI;
      EXPECT_LT(amplitude_error, 0.03) << names[mode] << " at T = " << bin.period << " s";
      EXPECT_LT(phase_error, 3.0) << names[mode] << " at T = " << bin.period << " s";
      worst_amplitude = std::max(worst_amplitude, amplitude_error);
      worst_phase = std::max(worst_phase, phase_error);
      ++compared;
    }
    std::printf("%s: H1 vs frequency-domain RAO at %d bins: worst amplitude %.2f %%, phase %.2f deg\n", names[mode],
                compared, 100 * worst_amplitude, worst_phase);
    EXPECT_GE(compared, 50) << names[mode];  // the comparison covers the sea's band, not a few bins
    RecordProperty(std::string(names[mode]) + "_amplitude_error", std::to_string(worst_amplitude));
    RecordProperty(std::string(names[mode]) + "_phase_error_deg", std::to_string(worst_phase));
  }
}


/// The RAO of `channel` in a rao.h5 of `heavesim rao`, per row, as complex numbers in the
/// file's units (rotations deg/m), with the rows' angular frequencies and coherences.
struct RaoRows {
  std::vector<double> frequencies, coherence;
  std::vector<std::complex<double>> values;
};
RaoRows read_rao_rows(const std::string& path, const std::string& channel) {
  const hdf5::Reader file(path, "rao.h5");
  RaoRows rows;
  rows.frequencies = file.read("/frequency").values;
  const std::vector<double> amplitude = file.read("/channels/" + channel + "/amplitude").values;
  const std::vector<double> phase = file.read("/channels/" + channel + "/phase").values;
  for (std::size_t r = 0; r < amplitude.size(); ++r) rows.values.push_back(std::polar(amplitude[r], phase[r] * M_PI / 180));
  if (file.has("/channels/" + channel + "/coherence")) rows.coherence = file.read("/channels/" + channel + "/coherence").values;
  return rows;
}

/// X(w) = Z(w)^-1 F(w, beta) with A(w), B(w) and F linear in w between the BEM points (as
/// the irregular-sea test above), from the WAMIT files and semisub.frc.
hydro::ComplexVector6 reference_rao(double w, double heading, const CaseDefinition& definition) {
  const hydro::BemData& bem = semisub();
  const Matrix6 stiffness = bem.hydrostatic_stiffness + case_matrix(definition, "mooring");
  const Matrix6 viscous = case_matrix(definition, "viscous");
  const auto [added_mass, damping] = radiation_at(w);
  const std::complex<double> i(0.0, 1.0);
  const ComplexMatrix6 impedance = (-w * w * (frc_mass_matrix() + added_mass) + stiffness).cast<std::complex<double>>() +
                                   i * w * (damping + viscous).cast<std::complex<double>>();
  return impedance.partialPivLu().solve(hydro::interpolate_excitation(bem.excitation, w, heading));
}

// `heavesim rao CASE --periods ...` end to end (case -> sweep of runs in worker processes
// -> fits -> rao.h5): surge, heave and pitch of the MSS semi in head seas at the BEM
// periods 8, 10, 12 and 15 s against the reference solved here, with the regular-wave
// test's bars and rule (3 %, 3 deg where the RAO is at least 10 % of the largest of its
// kind). The runs are the case's own: 800 s, 100 s ramp, fitted over the whole cycles of
// the last 400 s. Why that is steady: the slowest transients are the 100 s mooring modes
// at 5 % of critical, whose envelope falls by e^(-0.05 (2 pi / 100 s) t), to 0.28 at 400 s
// and 0.08 at 800 s; they sit a decade below the wave frequency, and over 30-50 wave
// cycles their projection on cos and sin of w is a further ~1/(w T_window) smaller. The
// regular-wave test above, with the same runs fitted over 5 cycles, measured at most 1.3 %
// and 2.1 deg. Measured here (2026-11-25): at most 0.99 % (surge, 15 s) and 2.1 deg
// (pitch, 8 s, where its RAO is small), the same runs as that test.
TEST(Platform6Dof, RaoCommandRegularSweepMatchesTheFrequencyDomainRao) {
  const std::string directory = ::testing::TempDir() + "rao_semisub_sweep";
  std::filesystem::remove_all(directory);
  const auto result = testing::run_command_line(
      testing::heavesim_binary() + " rao " + testing::source_path("cases/hydro/semisub_6dof_regular_wave.yaml") +
      " --periods 8,10,12,15 --set parameters.heading=pi --channel surge --channel heave --channel pitch -j 2 --no-plot -o " +
      directory);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::printf("%s", result.output.c_str());
  const CaseDefinition definition = case_definition("cases/hydro/semisub_6dof_regular_wave.yaml");
  double worst_amplitude = 0.0, worst_phase = 0.0;
  std::map<std::string, RaoRows> rows;
  for (const char* name : {"surge", "heave", "pitch"}) rows[name] = read_rao_rows(directory + "/rao.h5", name);
  const std::vector<double>& frequencies = rows["heave"].frequencies;
  ASSERT_EQ(frequencies.size(), 4u);
  for (std::size_t r = 0; r < frequencies.size(); ++r) {
    const double periods[] = {8, 10, 12, 15};
    EXPECT_NEAR(frequencies[r], 2 * M_PI / periods[r], 1e-12);
    const hydro::ComplexVector6 rao = reference_rao(frequencies[r], M_PI, definition);
    const double largest_translation = std::max({std::abs(rao[0]), std::abs(rao[2]), 0.05});
    for (const auto& [name, mode] : {std::pair{"surge", 0}, std::pair{"heave", 2}, std::pair{"pitch", 4}}) {
      const std::complex<double> expected = mode == 4 ? rao[mode] * (180 / M_PI) : rao[mode];  // the file: deg/m
      const std::complex<double> measured = rows[name].values[r];
      const double scale = mode < 3 ? largest_translation : std::max(std::abs(rao[4]), 0.05 / 20) * 180 / M_PI;
      const double amplitude_error = std::abs(std::abs(measured) / std::abs(expected) - 1.0);
      const double phase_error = std::abs(std::arg(measured / expected)) * 180 / M_PI;
      std::printf("T %4.1f %-5s: |X| %.4e  reference %.4e  amplitude error %5.2f %%  phase error %5.2f deg\n",
                  2 * M_PI / frequencies[r], name, std::abs(measured), std::abs(expected), 100 * amplitude_error, phase_error);
      if (std::abs(expected) < 0.1 * scale) continue;
      EXPECT_LT(amplitude_error, 0.03) << name << " at T = " << 2 * M_PI / frequencies[r];
      EXPECT_LT(phase_error, 3.0) << name << " at T = " << 2 * M_PI / frequencies[r];
      worst_amplitude = std::max(worst_amplitude, amplitude_error);
      worst_phase = std::max(worst_phase, phase_error);
    }
  }
  // The table's units and the CSV beside it.
  const hdf5::Reader file(directory + "/rao.h5", "rao.h5");
  EXPECT_EQ(file.text_attribute("/channels/heave/amplitude", "units").value_or(""), "m/m");
  EXPECT_EQ(file.text_attribute("/channels/pitch/amplitude", "units").value_or(""), "deg/m");
  std::ifstream csv(directory + "/rao.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("period [s],frequency [rad/s],surge amplitude [m/m],surge phase [deg],surge bem amplitude [m/m],"
                         "surge bem phase [deg],heave amplitude [m/m]",
                         0),
            0u)
      << header;
  RecordProperty("amplitude_error", std::to_string(worst_amplitude));
  RecordProperty("phase_error_deg", std::to_string(worst_phase));
}


// `heavesim rao OUT.h5` end to end on the 3-hour irregular run of the irregular-sea test
// above (JONSWAP Hs 4 m, Tp 10 s, head seas, 1000 components, window from 200 s): the
// command reads the elevation the run recorded at the reference point and the platform's
// motions from the file, picks 2048-sample segments (the largest power of two giving at
// least 15), and writes H1 with its coherence per bin of the sea's band. Compared here at
// every bin with coherence > 0.9 and |RAO| >= 10 % of the mode's largest over those bins
// with the reference solved in this file, bars 3 % and 3 deg as argued for the C++-level
// test above (same run, same estimator; what differs is only the path through the result
// file: float64 samples, the recorded elevation instead of the wave train's). Also draws
// the figure through scripts/plot_rao.py. Measured (2026-11-25): surge 2.92 % and 1.53 deg
// (104 bins), heave 1.45 % and 1.18 deg (74), pitch 2.77 % and 1.54 deg (106): the C++-level
// test's figures to the digits it prints.
TEST(Platform6Dof, RaoCommandH1MatchesTheFrequencyDomainRao) {
  const std::string run = ::testing::TempDir() + "semisub_irregular_1000.h5";
  const std::string directory = ::testing::TempDir() + "rao_semisub_h1";
  std::filesystem::remove_all(directory);
  const auto ran = testing::run_case("cases/hydro/semisub_6dof_irregular_sea.yaml", run,
                                     "-q --set waves.components=1000 --set output.evaluate_after=200 "
                                     "--set output.channels=[bodies,forces]");
  ASSERT_EQ(ran.exit_code, 0) << ran.output;
  const auto result = testing::run_command_line(testing::heavesim_binary() + " rao " + run +
                                                " --channel surge --channel heave --channel pitch -o " + directory);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::printf("%s", result.output.c_str());
  EXPECT_NE(result.output.find("segments of 2048 samples"), std::string::npos) << result.output;
  const CaseDefinition definition = case_definition("cases/hydro/semisub_6dof_irregular_sea.yaml");
  for (const auto& [name, mode] : {std::pair{"surge", 0}, std::pair{"heave", 2}, std::pair{"pitch", 4}}) {
    const RaoRows rows = read_rao_rows(directory + "/rao.h5", name);
    ASSERT_EQ(rows.coherence.size(), rows.values.size());
    std::vector<std::complex<double>> expected(rows.values.size());
    double largest = 0.0;
    for (std::size_t r = 0; r < rows.values.size(); ++r) {
      expected[r] = reference_rao(rows.frequencies[r], M_PI, definition)[mode] * (mode == 4 ? 180 / M_PI : 1.0);
      if (rows.coherence[r] > 0.9) largest = std::max(largest, std::abs(expected[r]));
    }
    int compared = 0;
    double worst_amplitude = 0.0, worst_phase = 0.0;
    for (std::size_t r = 0; r < rows.values.size(); ++r) {
      if (!(rows.coherence[r] > 0.9) || std::abs(expected[r]) < 0.1 * largest) continue;
      const double amplitude_error = std::abs(std::abs(rows.values[r]) / std::abs(expected[r]) - 1.0);
      const double phase_error = std::abs(std::arg(rows.values[r] / expected[r])) * 180 / M_PI;
      EXPECT_LT(amplitude_error, 0.03) << name << " at T = " << 2 * M_PI / rows.frequencies[r] << " s";
      EXPECT_LT(phase_error, 3.0) << name << " at T = " << 2 * M_PI / rows.frequencies[r] << " s";
      worst_amplitude = std::max(worst_amplitude, amplitude_error);
      worst_phase = std::max(worst_phase, phase_error);
      ++compared;
    }
    std::printf("%s: rao OUT.h5 vs the frequency-domain RAO at %d bins: worst amplitude %.2f %%, phase %.2f deg\n", name,
                compared, 100 * worst_amplitude, worst_phase);
    EXPECT_GE(compared, 50) << name;
    RecordProperty(std::string(name) + "_amplitude_error", std::to_string(worst_amplitude));
    RecordProperty(std::string(name) + "_phase_error_deg", std::to_string(worst_phase));
  }
  // The figure: a PNG (its signature) of some size.
  std::ifstream png(directory + "/rao.png", std::ios::binary);
  char signature[8] = {};
  png.read(signature, 8);
  EXPECT_EQ(std::string(signature + 1, 3), "PNG");
  EXPECT_GT(std::filesystem::file_size(directory + "/rao.png"), 20000u);
}

}  // namespace
}  // namespace heavesim::test_platform_6dof
