// C3: gas-spring energy. The work the pneumatic compensator's gas does on the moving
// side, integral F ds, against the polytropic closed form
//   W(s) = (p0 V0 - p V) / (n - 1) - p_atm (V - V0),  V = V0 + A s,  p V^n = p0 V0^n
// (validation/oracles/polytropic_gas.hpp):
//  * along a prescribed, non-monotonic +-3.3 m stroke history, with W integrated as a
//    state by the kernel's integrators (validation/checks/prescribed_motion.hpp), for the
//    algebraic gas law and for the gas-temperature state (no heat exchange: the
//    first-law ODE must reproduce the polytrope);
//  * through the whole application: a mass swinging +-3 m on the gas spring
//    (cases/validation/c3_gas_spring.yaml), where W is the change of kinetic plus
//    gravitational energy along the integrated trajectory.
#include <cmath>

#include <fmt/format.h>

#include "control/pneumatic/pneumatic_compensator.hpp"
#include "kernel/algorithms/energy.hpp"
#include "kernel/integrators/integrator.hpp"
#include "samples/oscillators.hpp"
#include "validation/checks/prescribed_motion.hpp"
#include "validation/checks/validation_suite.hpp"
#include "validation/oracles/polytropic_gas.hpp"

namespace heavesim::validation {
namespace {

using namespace default_gas_spring;
constexpr double p0 = 15e6;

// Starts at mid-stroke, where p0 and T0 are given, and swings non-monotonically.
double stroke(double t) { return 2.5 * std::sin(0.7 * t) + 0.8 * std::sin(1.9 * t); }
double stroke_rate(double t) { return 2.5 * 0.7 * std::cos(0.7 * t) + 0.8 * 1.9 * std::cos(1.9 * t); }

/// Largest |W - W_ref| / max |W_ref| over 60 s of the stroke history.
double prescribed_history_error(const IntegratorSettings& settings, bool gas_state) {
  auto model = samples::vertical_slider(290e3);
  PrescribedMotionSystem system(model, [](double t, VectorX& q, VectorX& v) {
    q[0] = stroke(t);
    v[0] = stroke_rate(t);
  });
  PneumaticParameters p;
  p.piston_area = A;
  p.gas_volume = V0;
  p.gas_pressure = p0;
  p.exponent_compression = p.exponent_expansion = n;
  if (gas_state) p.cooling = GasCooling{std::numeric_limits<double>::infinity(), p.initial_temperature};
  system.add_force_element(std::make_unique<PneumaticCompensator>("gas", StrokeAxis::on_joint(*model, 1, 0.0), p));
  auto integrator = make_integrator(settings, system);
  integrator->initialize(0.0, system.initial_state());
  double error = 0.0, scale = 0.0;
  for (int k = 1; k <= 600; ++k) {
    const double t = 0.1 * k;
    integrator->advance_to(t);
    const double reference = oracle::gas_spring_work(p0, V0, A, n, p_atm, stroke(t));
    error = std::max(error, std::abs(integrator->state()[system.size() - 1] - reference));
    scale = std::max(scale, std::abs(reference));
  }
  return error / scale;
}

}  // namespace

std::vector<ValidationRow> check_c3_gas_spring_energy() {
  std::vector<ValidationRow> rows;
  IntegratorSettings dopri;
  dopri.method = IntegrationMethod::dopri5;
  dopri.relative_tolerance = 1e-10;
  dopri.absolute_tolerance = 1e-10;
  IntegratorSettings ida = dopri;
  ida.method = IntegrationMethod::ida;
  IntegratorSettings rk4;
  rk4.method = IntegrationMethod::rk4;
  rk4.step = 1e-2;
  const std::string subject = "prescribed +-3.3 m stroke history, 60 s";
  for (const auto& [label, settings] : {std::pair{"Dormand-Prince 1e-10", dopri}, std::pair{"IDA 1e-10", ida},
                                        std::pair{"RK4 h = 10 ms", rk4}})
    rows.push_back({"C3", subject + ", algebraic gas law, " + label, "integral F ds vs polytropic work, relative",
                    prescribed_history_error(settings, false), 1e-6});
  rows.push_back({"C3", subject + ", gas-temperature state, IDA 1e-10", "integral F ds vs polytropic work, relative",
                  prescribed_history_error(ida, true), 1e-6});

  // Through the application: W = change of kinetic + gravitational energy.
  constexpr double mass = 290000.0;
  const double balance = p_atm + mass * g / A;  // the case's gas_pressure: balance at s = 0
  double energy0 = 0.0, error = 0.0, scale = 0.0, largest_stroke = 0.0;
  bool first = true;
  run_case("cases/validation/c3_gas_spring.yaml", {}, [&](double, const MultibodySystem& system) {
    const double s = system.configuration()[0];
    const double energy = mechanical_energy(system);
    if (first) energy0 = energy, first = false;
    const double reference = oracle::gas_spring_work(balance, V0, A, n, p_atm, s);
    error = std::max(error, std::abs((energy - energy0) - reference));
    scale = std::max(scale, std::abs(reference));
    largest_stroke = std::max(largest_stroke, std::abs(s));
  });
  rows.push_back({"C3", fmt::format("c3_gas_spring.yaml: 290 t swinging +-{:.2f} m, IDA 1e-11", largest_stroke),
                  "kinetic + gravity energy change vs polytropic work, relative", error / scale, 1e-6});
  return rows;
}

}  // namespace heavesim::validation
