// The hydro force elements on a body in the multibody kernel: the MSS semi on a
// vertical prismatic joint (heave only; heave couples with no other mode for this
// doubly symmetric hull in head seas), A(inf) in its spatial inertia.
//   H3: heave free decay with linear coefficients against the closed forms;
//   H4: regular-wave heave RAO from time-domain runs (least-squares fit after the
//       ramp) against the frequency-domain RAO of the same coefficients.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <random>

#include <Eigen/QR>

#include "io/bem/wamit_reader.hpp"
#include "hydro/elements/linear_body_loads.hpp"
#include "hydro/elements/nonlinear_hydrostatics.hpp"
#include "hydro/elements/radiation_convolution.hpp"
#include "hydro/elements/radiation_memory.hpp"
#include "hydro/elements/wave_excitation.hpp"
#include "hydro/excitation/excitation_interpolation.hpp"
#include "hydro/waves/wave_spectrum.hpp"
#include "hydro/radiation/added_mass.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/integrators/integrator.hpp"
#include "kernel/system/multibody_system.hpp"
#include "samples/floating_bodies.hpp"
#include "tests/test_support.hpp"
#include "validation/checks/harmonic_fit.hpp"

namespace heavesim::hydro {
namespace {

constexpr double rho = 1025.0, g = 9.81, mass = samples::mss_semisub_mass;  // semisub.frc

const BemData& semisub() {
  static const BemData bem = bem::read_wamit(testing::source_path("data/mss_semisub/semisub"), {rho, g, 1.0});
  return bem;
}

/// The semi on a vertical slide (samples/floating_bodies.hpp), with A(inf) from WAMIT.
std::shared_ptr<const Model> heaving_semisub(const Matrix6& added_mass_wamit) {
  return samples::heaving_mss_semisub(added_inertia_in_body_frame(added_mass_wamit));
}

/// Buoyancy (weight-balancing, so the mean free surface is the equilibrium) plus the
/// BEM restoring matrix.
std::unique_ptr<ForceElement> hydrostatics(const Model& model) {
  Vector6 buoyancy = Vector6::Zero();
  buoyancy[2] = mass * g;
  return std::make_unique<LinearRestoring>("hydrostatics", model.link_index("semisub"), semisub().hydrostatic_stiffness,
                                           buoyancy, Transform::Identity());
}

std::string fmt_e(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3e", value);
  return text;
}

std::unique_ptr<Integrator> rk4(double step, MultibodySystem& system) {
  IntegratorSettings settings;
  settings.method = IntegrationMethod::rk4;
  settings.step = step;
  return make_integrator(settings, system);
}

// H3: free decay from 1 m with constant A33 = A33(w = 0) (the natural period is long),
// C33 from the .hst and a
// linear damping of 0 or 5 % of critical; the heave against
//   x(t) = x0 e^{-z wn t} (cos wd t + z / sqrt(1 - z^2) sin wd t),
//   wn = sqrt(C33 / (m + A33)), wd = wn sqrt(1 - z^2);
// period from the zero crossings against 2 pi / wd.
TEST(HydroBodyResponse, H3HeaveFreeDecayMatchesClosedForm) {
  const RadiationData& r = semisub().radiation;
  const double A33 = r.added_mass_zero(2, 2), C33 = semisub().hydrostatic_stiffness(2, 2);
  const double wn = std::sqrt(C33 / (mass + A33));
  EXPECT_NEAR(2 * M_PI / wn, 21.9, 0.1);  // docs/physics/hydrodynamics.md §12: about 21.9 s
  for (double zeta : {0.0, 0.05}) {
    auto model = heaving_semisub(r.added_mass_zero);
    MultibodySystem system(model);
    system.add_force_element(hydrostatics(*model));
    Matrix6 damping = Matrix6::Zero();
    damping(2, 2) = 2 * zeta * wn * (mass + A33);
    system.add_force_element(std::make_unique<BodyDamping>("viscous", model->link_index("semisub"), damping));
    const double x0 = 1.0, wd = wn * std::sqrt(1 - zeta * zeta);
    auto integrator = rk4(0.02, system);
    integrator->initialize(0.0, system.initial_state(VectorX::Constant(1, x0), VectorX::Zero(1)));
    double amplitude_error = 0.0, previous = x0;
    std::vector<double> crossings;
    for (int k = 1; k <= 7500; ++k) {  // 150 s, about 7 periods
      const double t = 0.02 * k;
      integrator->advance_to(t);
      const double x = integrator->state()[0];
      const double exact = x0 * std::exp(-zeta * wn * t) * (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t));
      amplitude_error = std::max(amplitude_error, std::abs(x - exact));
      if ((previous > 0) != (x > 0)) crossings.push_back(t - 0.02 * x / (x - previous));
      previous = x;
    }
    ASSERT_GE(crossings.size(), 10u);
    const double period = 2 * (crossings.back() - crossings.front()) / (crossings.size() - 1);
    EXPECT_NEAR(period / (2 * M_PI / wd), 1.0, 0.001) << "zeta " << zeta;
    EXPECT_LT(amplitude_error / x0, 0.005) << "zeta " << zeta;
    RecordProperty("period_error_zeta" + std::to_string(int(zeta * 100)), fmt_e(period / (2 * M_PI / wd) - 1));
    RecordProperty("amplitude_error_zeta" + std::to_string(int(zeta * 100)), fmt_e(amplitude_error / x0));
  }
}

// H4: regular head waves (H = 2 m, cosine ramp 100 s) at four BEM periods; A(inf) in
// the inertia, the radiation memory as a 12-state realisation of K(t) (60 s), the
// excitation X3(w, 0) of the .3 file, C33 of the .hst and 5 % critical viscous damping
// (so the free transient dies out; SIMO's advice for semis). The heave amplitude and
// phase (least-squares fit over the last 5 periods of 800 s) against
//   xi = X3 / (C33 - w^2 (m + A(inf)) + i w (B_visc + H(i w))),
// H(i w) = B(w) + i w (A(w) - A(inf)) the transfer function of the same realisation.
TEST(HydroBodyResponse, H4RegularWaveRaoMatchesFrequencyDomain) {
  const BemData& bem = semisub();
  const RadiationData& r = bem.radiation;
  const RetardationKernel kernel = retardation_kernel(r, 60.0, 0.05);
  const ModePairStateSpace heave_memory = realize_kernel_entry(kernel, 2, 2, 12);
  const double A33 = r.added_mass_infinite(2, 2), C33 = bem.hydrostatic_stiffness(2, 2);
  const double wn = std::sqrt(C33 / (mass + A33)), b_visc = 2 * 0.05 * wn * (mass + A33);
  double worst_amplitude = 0.0, worst_phase = 0.0, worst_bem_amplitude = 0.0;
  for (double period : {8.0, 10.0, 12.0, 15.0}) {
    auto model = heaving_semisub(r.added_mass_infinite);
    const int link = model->link_index("semisub");
    MultibodySystem system(model);
    system.add_force_element(hydrostatics(*model));
    Matrix6 damping = Matrix6::Zero();
    damping(2, 2) = b_visc;
    system.add_force_element(std::make_unique<BodyDamping>("viscous", link, damping));
    system.add_force_element(std::make_unique<RadiationMemory>("radiation", link, std::vector{heave_memory}));
    const WaveTrain wave = regular_wave(2.0, period, 0.0, 0.0, infinite_depth, Ramp{RampKind::cosine, 100.0}, g);
    system.add_force_element(std::make_unique<WaveExcitation>("excitation", link, bem.excitation, wave));
    auto integrator = rk4(0.05, system);
    integrator->initialize(0.0, system.initial_state(VectorX::Zero(1), VectorX::Zero(1)));
    const double w = 2 * M_PI / period, t_end = 800.0, t_fit = t_end - 5 * period;
    std::vector<double> times, heave;
    for (int k = 1; k * 0.05 <= t_end + 1e-9; ++k) {
      integrator->advance_to(k * 0.05);
      if (k * 0.05 >= t_fit) {
        times.push_back(k * 0.05);
        heave.push_back(integrator->state()[0]);
      }
    }
    const std::complex<double> time_domain = validation::fit_harmonic(times, heave, w);  // x = Re[xi e^{i w t}], wave amplitude 1 m
    const std::complex<double> X3 = bem.excitation.force[0][std::find(bem.excitation.angular_frequencies.begin(),
                                                                        bem.excitation.angular_frequencies.end(), w) -
                                                              bem.excitation.angular_frequencies.begin()][2];
    const std::complex<double> i(0.0, 1.0);
    const std::complex<double> frequency_domain =
        X3 / (C33 - w * w * (mass + A33) + i * w * (b_visc + frequency_response(heave_memory, w)));
    const double amplitude_error = std::abs(std::abs(time_domain) / std::abs(frequency_domain) - 1.0);
    const double phase_error = std::abs(std::arg(time_domain / frequency_domain)) * 180.0 / M_PI;
    EXPECT_LT(amplitude_error, 0.01) << "T = " << period;
    EXPECT_LT(phase_error, 1.0) << "T = " << period;
    worst_amplitude = std::max(worst_amplitude, amplitude_error);
    worst_phase = std::max(worst_phase, phase_error);
    // For the record: the same with WAMIT's A33(w), B33(w) at this frequency.
    const size_t n = std::find(r.angular_frequencies.begin(), r.angular_frequencies.end(), w) - r.angular_frequencies.begin();
    const std::complex<double> bem_rao =
        X3 / (C33 - w * w * (mass + r.added_mass[n](2, 2)) + i * w * (b_visc + r.damping[n](2, 2)));
    worst_bem_amplitude = std::max(worst_bem_amplitude, std::abs(std::abs(time_domain) / std::abs(bem_rao) - 1.0));
  }
  RecordProperty("amplitude_error", fmt_e(worst_amplitude));
  RecordProperty("phase_error_deg", fmt_e(worst_phase));
  RecordProperty("amplitude_error_vs_bem_coefficients", std::to_string(worst_bem_amplitude));
}

// Irregular waves: three components at BEM periods (9, 12, 15 s; equal-Δω-like
// amplitudes and random phases) through the same model as H4; after the transient
// the heave must be the superposition of the three frequency-domain responses.
TEST(HydroBodyResponse, IrregularWaveResponseIsTheSumOfRaoResponses) {
  const BemData& bem = semisub();
  const RadiationData& r = bem.radiation;
  const ModePairStateSpace memory = realize_kernel_entry(retardation_kernel(r, 60.0, 0.05), 2, 2, 12);
  const double A33 = r.added_mass_infinite(2, 2), C33 = bem.hydrostatic_stiffness(2, 2);
  const double wn = std::sqrt(C33 / (mass + A33)), b_visc = 2 * 0.05 * wn * (mass + A33);
  std::vector<WaveComponent> components;
  const double periods[] = {9.0, 12.0, 15.0}, amplitudes[] = {0.8, 1.2, 0.6}, phases[] = {0.3, 2.0, 4.4};
  for (int j = 0; j < 3; ++j) {
    const double w = 2 * M_PI / periods[j];
    components.push_back({amplitudes[j], w, w * w / g, 0.0, phases[j]});
  }
  const WaveTrain sea(components, Ramp{RampKind::cosine, 100.0});
  auto model = heaving_semisub(r.added_mass_infinite);
  const int link = model->link_index("semisub");
  MultibodySystem system(model);
  system.add_force_element(hydrostatics(*model));
  Matrix6 damping = Matrix6::Zero();
  damping(2, 2) = b_visc;
  system.add_force_element(std::make_unique<BodyDamping>("viscous", link, damping));
  system.add_force_element(std::make_unique<RadiationMemory>("radiation", link, std::vector{memory}));
  system.add_force_element(std::make_unique<WaveExcitation>("excitation", link, bem.excitation, sea));
  auto integrator = rk4(0.05, system);
  integrator->initialize(0.0, system.initial_state(VectorX::Zero(1), VectorX::Zero(1)));
  std::complex<double> rao[3];
  for (int j = 0; j < 3; ++j) {
    const double w = components[j].angular_frequency;
    const size_t n = std::find_if(r.angular_frequencies.begin(), r.angular_frequencies.end(),
                                  [&](double x) { return std::abs(x - w) < 1e-12; }) - r.angular_frequencies.begin();
    ASSERT_LT(n, r.angular_frequencies.size());
    rao[j] = bem.excitation.force[0][n][2] /
             (C33 - w * w * (mass + A33) + std::complex<double>(0, w) * (b_visc + frequency_response(memory, w)));
  }
  double peak = 0.0, error = 0.0;
  for (int k = 1; k * 0.05 <= 900.0 + 1e-9; ++k) {
    const double t = k * 0.05;
    integrator->advance_to(t);
    if (t < 700.0) continue;
    double expected = 0.0;
    for (int j = 0; j < 3; ++j)
      expected += (rao[j] * amplitudes[j] * std::polar(1.0, components[j].angular_frequency * t + phases[j])).real();
    peak = std::max(peak, std::abs(expected));
    error = std::max(error, std::abs(integrator->state()[0] - expected));
  }
  EXPECT_LT(error / peak, 0.01);
  RecordProperty("superposition_error", fmt_e(error / peak));
  // The excitation at a mean position x0 down-wave is the excitation at the origin
  // delayed by the travel time of each component (checked on one component).
  const WaveTrain single({components[1]});
  const double x0 = 40.0, c = components[1].angular_frequency / components[1].wave_number;
  const WaveExcitation at_origin("origin", link, bem.excitation, single);
  const WaveExcitation down_wave("down", link, bem.excitation, single, Eigen::Vector2d(x0, 0.0));
  for (double t : {100.0, 103.0, 107.5})
    EXPECT_NEAR(down_wave.load(t)[2], at_origin.load(t - x0 / c)[2], 1e-6 * std::abs(rao[1]) * C33);
  // The element keeps its last load (an implicit integrator asks for it many times at
  // one t): repeated and alternating times give what a new element gives at each time.
  for (double t : {100.0, 100.0, 103.0, 100.0, 0.0}) {
    const WaveExcitation fresh("fresh", link, bem.excitation, single);
    EXPECT_TRUE(at_origin.load(t) == fresh.load(t)) << "t = " << t;
  }
}

// WaveExcitation's evaluation (one sincos per component, a 7 x N product, the last time
// kept) against the sum written out: F = R(t) sum_j Re[X(w_j, beta) a_j
// e^{i (w_j t + phi_j - k_j x0 . e_beta)}], and its elevation channel against WaveTrain's,
// at repeated and new times of a 200-component sea off the origin (1e-10 of the sum of
// the terms: the phases w t reach 3e4 rad at 3 hours, whose rounding is ~4e-12 rad).
TEST(HydroBodyResponse, WaveExcitationSumsTheComponents) {
  const BemData& bem = semisub();
  IrregularSeaSettings settings;
  settings.num_components = 200;
  settings.heading = 2.6;
  settings.ramp = Ramp{RampKind::cosine, 30.0};
  const WaveTrain sea = irregular_sea(Jonswap(4.0, 10.0, 3.3), settings);
  const Eigen::Vector2d mean(40.0, -10.0);
  const WaveExcitation element("excitation", 1, bem.excitation, sea, mean);
  for (double t : {0.0, 12.5, 12.5, 123.4, 10800.0, 123.4}) {
    Vector6 expected = Vector6::Zero(), scale = Vector6::Zero();
    for (const WaveComponent& c : sea.components()) {
      const double phase = c.angular_frequency * t + c.phase -
                           c.wave_number * (mean.x() * std::cos(c.heading) + mean.y() * std::sin(c.heading));
      const ComplexVector6 X = interpolate_excitation(bem.excitation, c.angular_frequency, c.heading) * c.amplitude;
      for (int i = 0; i < 6; ++i) {
        expected[i] += (X[i] * std::polar(1.0, phase)).real();
        scale[i] += std::abs(X[i]);
      }
    }
    expected *= sea.ramp()(t);
    const Vector6 load = element.load(t);
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(load[i], expected[i], 1e-10 * scale[i]) << "t " << t << " mode " << i;
    EXPECT_NEAR(element.elevation(t), sea.elevation(t, mean.x(), mean.y()), 1e-10) << "t " << t;
  }
  // The load at a time does not depend on the times asked before, bit for bit: reached by
  // small steps forward, by a jump from far ahead, and by a step back within the grid's
  // block (a recorder behind the integrator).
  {
    const WaveExcitation walked("walked", 1, bem.excitation, sea, mean), jumped("jumped", 1, bem.excitation, sea, mean),
        stepped_back("back", 1, bem.excitation, sea, mean);
    for (double t = 420.0; t < 437.3; t += 0.013) walked.load(t);
    jumped.load(9000.0);
    stepped_back.load(440.9);
    for (const WaveExcitation* element : {&walked, &jumped, &stepped_back}) {
      const Vector6 load = element->load(437.3), reference = WaveExcitation("fresh", 1, bem.excitation, sea, mean).load(437.3);
      for (int i = 0; i < 6; ++i) EXPECT_EQ(load[i], reference[i]) << element->name() << " mode " << i;
    }
  }
  // The largest difference of a load from the direct sum, relative to each mode's scale.
  const auto error_of = [&](double at, const Vector6& load) {
    Vector6 expected = Vector6::Zero(), scale = Vector6::Zero();
    for (const WaveComponent& c : sea.components()) {
      const ComplexVector6 X = interpolate_excitation(bem.excitation, c.angular_frequency, c.heading) * c.amplitude;
      const double phase = c.angular_frequency * at + c.phase -
                           c.wave_number * (mean.x() * std::cos(c.heading) + mean.y() * std::sin(c.heading));
      for (int i = 0; i < 6; ++i) {
        expected[i] += (X[i] * std::polar(1.0, phase)).real();
        scale[i] += std::abs(X[i]);
      }
    }
    expected *= sea.ramp()(at);
    return ((load - expected).array() / scale.array()).abs().maxCoeff();
  };
  // The times of fixed-step RK4 (h = 0.1 s: t, t + h/2 twice, t + h, accumulated as the
  // integrator does), for 3 hours.
  double t = 0.0, worst = 0.0;
  for (long step = 0; step < 108000; ++step) {
    for (double stage : {t, t + 0.05, t + 0.05, t + 0.1}) {
      const Vector6 load = element.load(stage);
      if (step % 997 == 0) worst = std::max(worst, error_of(stage, load));
    }
    t += 0.1;
  }
  EXPECT_LT(worst, 1e-9);
  RecordProperty("rotated_phasor_error", fmt_e(worst));
  // The times of a variable-step integrator for 3 hours: steps of 1 ms to 0.4 s, every
  // tenth one retried from a point part-way back (IDA after a failed error test), where the
  // phasors come from the grid and the in-cell polynomial.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> step(1e-3, 0.4), back(0.0, 1.0);
  double variable_worst = 0.0;
  long evaluations = 0;
  for (double time = 0.0; time < 10800.0; time += step(random)) {
    for (const double at : {time, evaluations % 10 == 0 ? time - back(random) * 0.4 : time}) {
      const Vector6 load = element.load(at);
      if (++evaluations % 997 == 0 && at >= 0.0) variable_worst = std::max(variable_worst, error_of(at, load));
    }
  }
  EXPECT_LT(variable_worst, 1e-9);
  RecordProperty("variable_step_phasor_error", fmt_e(variable_worst));
}

// LinearRestoring and BodyDamping on a free body away from the origin: the
// displacement, the reference-point velocity (world axes) and the load's moment
// about the world origin, worked by hand.
TEST(HydroBodyResponse, LinearLoadsActAtTheBodyReferencePoint) {
  const auto hull = samples::free_floating_body("hull", Inertia(1e5, Vector3::Zero(), Matrix3::Identity() * 1e6));
  const Model& model = *hull;
  Data data(model);
  const double yaw = 0.1;
  const Vector3 p(5.0, -2.0, 1.0);
  VectorX q = model.neutral_configuration(), v = VectorX::Zero(6);
  q.head<3>() = p;
  q.segment<4>(3) << std::cos(yaw / 2), 0, 0, std::sin(yaw / 2);
  v << 0, 0, 0.2, 1.0, 0, 0;  // body axes: yaw rate 0.2 rad/s, surge 1 m/s
  update_positions(model, data, q);
  update_velocities(model, data, q, v);
  const int link = model.link_index("hull");
  const Vector6 stiffness_diagonal = (Vector6() << 1, 2, 3, 4, 5, 6).finished() * 1e4;
  Vector6 f0 = Vector6::Zero();
  f0[2] = 7e5;
  LinearRestoring spring("mooring", link, stiffness_diagonal.asDiagonal(), f0, Transform::Identity());
  BodyDamping damper("drag", link, Matrix6::Identity() * 10.0, Vector6::Constant(3.0));
  AppliedForces forces(model);
  spring.apply(0.0, model, data, VectorX(), forces);
  damper.apply(0.0, model, data, VectorX(), forces);
  // xi = [p; 0, 0, yaw]; velocity = [R (1, 0, 0); (0, 0, 0.2)].
  Vector6 xi, velocity;
  xi << p, 0, 0, yaw;
  velocity << std::cos(yaw), std::sin(yaw), 0, 0, 0, 0.2;
  const Vector6 load = f0 - stiffness_diagonal.cwiseProduct(xi) - 10.0 * velocity -
                       3.0 * velocity.cwiseProduct(velocity.cwiseAbs());
  const Vector3 F = load.head<3>(), M = load.tail<3>() + p.cross(F);
  EXPECT_LE((forces.external_force_world[link].linear() - F).norm(), 1e-9 * F.norm());
  EXPECT_LE((forces.external_force_world[link].angular() - M).norm(), 1e-9 * M.norm());
}

// The convolution element against the state-space element in the same run as H4
// (T = 12 s and 15 s): heave histories over the last 5 periods within 1 % of the
// amplitude, both from the same 60 s kernel.
TEST(HydroBodyResponse, ConvolutionElementMatchesStateSpaceElement) {
  const BemData& bem = semisub();
  const RadiationData& r = bem.radiation;
  const RetardationKernel kernel = retardation_kernel(r, 60.0, 0.05);
  const ModePairStateSpace heave_memory = realize_kernel_entry(kernel, 2, 2, 12);
  const double A33 = r.added_mass_infinite(2, 2), C33 = bem.hydrostatic_stiffness(2, 2);
  const double wn = std::sqrt(C33 / (mass + A33)), b_visc = 2 * 0.05 * wn * (mass + A33);
  for (double period : {12.0, 15.0}) {
    std::vector<double> heave[2];
    for (int variant = 0; variant < 2; ++variant) {
      auto model = heaving_semisub(r.added_mass_infinite);
      const int link = model->link_index("semisub");
      MultibodySystem system(model);
      system.add_force_element(hydrostatics(*model));
      Matrix6 damping = Matrix6::Zero();
      damping(2, 2) = b_visc;
      system.add_force_element(std::make_unique<BodyDamping>("viscous", link, damping));
      if (variant == 0)
        system.add_force_element(std::make_unique<RadiationMemory>("radiation", link, std::vector{heave_memory}));
      else
        system.add_force_element(std::make_unique<RadiationConvolution>("radiation", link, kernel));
      const WaveTrain wave = regular_wave(2.0, period, 0.0, 0.0, infinite_depth, Ramp{RampKind::cosine, 100.0}, g);
      system.add_force_element(std::make_unique<WaveExcitation>("excitation", link, bem.excitation, wave));
      auto integrator = rk4(0.05, system);
      integrator->initialize(0.0, system.initial_state(VectorX::Zero(1), VectorX::Zero(1)));
      for (int k = 1; k * 0.05 <= 500.0 + 1e-9; ++k) {
        integrator->advance_to(k * 0.05);
        if (k * 0.05 >= 500.0 - 5 * period) heave[variant].push_back(integrator->state()[0]);
      }
    }
    double peak = 0.0, difference = 0.0;
    for (size_t n = 0; n < heave[0].size(); ++n) {
      peak = std::max(peak, std::abs(heave[0][n]));
      difference = std::max(difference, std::abs(heave[0][n] - heave[1][n]));
    }
    EXPECT_LT(difference / peak, 0.01) << "T = " << period;
    RecordProperty("convolution_vs_state_space_T" + std::to_string(int(period)), fmt_e(difference / peak));
  }
}

// Nonlinear buoyancy through the kernel: a wall-sided box (10 x 8 x 6 m, CoG at its
// centre) floating freely (6-DoF joint) at 3 m draft, released 0.5 m low. While the
// waterline stays on the walls the clipped buoyancy is exactly linear in heave, so
//   z(t) = z_eq - 0.5 cos(w t),  w = sqrt(rho g A_wp / m),
// with no added mass in this element; nothing else may move (a pitch or sway drift
// would mean a wrong moment or a lateral force from the clipping).
TEST(HydroBodyResponse, FreeFloatingBoxHeavesAtTheHydrostaticPeriod) {
  const double L = 10.0, B = 8.0, H = 6.0, T = 3.0, m = rho * L * B * T;
  auto model = samples::free_floating_body(
      "box", Inertia(m, Vector3::Zero(), Vector3(m * (B * B + H * H) / 12, m * (L * L + H * H) / 12,
                                                 m * (L * L + B * B) / 12).asDiagonal()),
      std::nullopt, Vector3(0, 0, -g));
  MultibodySystem system(model);
  system.add_force_element(std::make_unique<NonlinearHydrostatics>("buoyancy", model->link_index("box"),
                                                                   box_mesh(Vector3(L, B, H), Vector3::Zero(), 4), rho, g));
  const double z_eq = 0.5 * H - T, w = std::sqrt(rho * g * L * B / m);
  VectorX q = model->neutral_configuration();
  q[2] = z_eq - 0.5;
  auto integrator = rk4(0.01, system);
  integrator->initialize(0.0, system.initial_state(q, VectorX::Zero(6)));
  double heave_error = 0.0, other_motion = 0.0;
  for (int k = 1; k <= 3000; ++k) {
    const double t = 0.01 * k;
    integrator->advance_to(t);
    const VectorX& y = integrator->state();
    heave_error = std::max(heave_error, std::abs(y[2] - (z_eq - 0.5 * std::cos(w * t))));
    other_motion = std::max({other_motion, std::abs(y[0]), std::abs(y[1]), std::abs(y[4]), std::abs(y[5]), std::abs(y[6])});
  }
  EXPECT_LT(heave_error, 1e-7);
  EXPECT_LT(other_motion, 1e-12);
  RecordProperty("heave_error_m", fmt_e(heave_error));
}

}  // namespace
}  // namespace heavesim::hydro
