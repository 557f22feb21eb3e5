// Reads and checks prescribed motions f(t) (docs/case-format.md, "drivers[i]").
#include "app/case/motion_reader.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "kernel/math/numerical_error.hpp"

namespace heavesim {

std::shared_ptr<const TimeFunction> read_motion(const NodeReader& item, const std::string& name,
                                                const ExpressionContext& expressions) {
  auto expression = [&](const std::string& key) -> std::optional<std::string> {
    auto node = item.optional(key);
    if (!node) return std::nullopt;
    if (!node->node().is_scalar()) node->fail("an expression of t such as 8 + 3*sin(t)");
    // Each expression alone, so that an error points at the right key.
    try {
      TimeFunction(name, node->node().scalar, std::nullopt, std::nullopt, expressions.parameters());
    } catch (const std::invalid_argument& e) {
      node->fail(node->node().describe() + " (" + e.what() + ")", "an expression of t such as 8 + 3*sin(t)");
    }
    return node->node().scalar;
  };
  item["position"];  // required: reports a missing key
  const std::string position = *expression("position");
  const std::optional<std::string> velocity = expression("velocity"), acceleration = expression("acceleration");
  if (velocity.has_value() != acceleration.has_value())
    item[velocity ? "velocity" : "acceleration"].fail("only one of velocity and acceleration",
                                                      "both (the exact derivatives of position) or neither");
  return std::make_shared<const TimeFunction>(name, position, velocity, acceleration, expressions.parameters());
}

namespace {

/// The times at which a case's expressions of t are evaluated before the run: the
/// output times or 1000 points over the run, whichever is finer (at most 1e5, so that
/// `check` stays quick), t_end included.
std::vector<double> expression_check_times(const CaseDefinition& definition) {
  const double t0 = definition.solver.t_start, t1 = definition.solver.t_end;
  const double samples = (t1 - t0) / definition.output.interval;
  const long intervals = static_cast<long>(std::clamp(std::ceil(samples), 1000.0, 1e5));
  std::vector<double> times;
  times.reserve(intervals + 1);
  for (long k = 0; k < intervals; ++k) times.push_back(t0 + (t1 - t0) * static_cast<double>(k) / intervals);
  times.push_back(t1);
  return times;
}

/// Refuses at `key_path` an expression of t that is not finite somewhere in the run
/// (sqrt(1 - t) on a 2 s run): bad input, found before running rather than reported as
/// a numerical failure when the run reaches it. `differenced`: its derivatives come
/// from central differences, which also read it 2 difference steps either side.
void check_finite_over_run(const TimeFunction& function, bool differenced, const std::vector<double>& times,
                           const CaseDefinition& definition, const std::string& key_path) {
  try {
    for (const double t : times)
      if (differenced)
        function(t);
      else
        function.position(t);
  } catch (const NumericalError& error) {
    throw definition.error_at(
        key_path, fmt::format("{} at t = {:.6g} s", error.what(), error.time()),
        fmt::format("an expression of t that is finite over the whole run, t = {:g} .. {:g} s{}",
                    definition.solver.t_start, definition.solver.t_end,
                    differenced ? fmt::format(" (and {:g} s either side, where the central differences that stand "
                                              "in for velocity and acceleration read it)",
                                              2 * TimeFunction::difference_step)
                                : ""));
  }
}

/// Every expression of t in the case -- each driver's position, velocity and
/// acceleration, each joint torque -- evaluated over the run before it starts.
void check_expressions_over_run(const CaseDefinition& definition, const ExpressionContext& expressions,
                                const std::optional<NodeReader>& drivers) {
  const std::vector<double> times = expression_check_times(definition);
  if (drivers) {
    const std::vector<NodeReader> items = drivers->items();
    for (std::size_t d = 0; d < definition.drivers.size(); ++d) {
      const bool differenced = !items[d].has("velocity");
      for (const char* key : {"position", "velocity", "acceleration"}) {
        const std::optional<NodeReader> expression = items[d].optional(key);
        if (!expression) continue;
        const TimeFunction alone(definition.drivers[d].name, expression->node().scalar, std::nullopt, std::nullopt,
                                 expressions.parameters());
        check_finite_over_run(alone, differenced && std::string(key) == "position", times, definition,
                              expression->path());
      }
    }
  }
  for (const ForceDefinition& force : definition.forces)
    if (const auto* torque = std::get_if<JointTorqueDefinition>(&force.kind))
      check_finite_over_run(*torque->torque, false, times, definition, definition.item_paths.at(force.name) + ".torque");
}

/// Explicit driver derivatives must be the derivatives of the position (a typo in
/// `velocity` would otherwise fight the position constraint): compared with central
/// differences at 21 times over the run. The tolerance at each time is the
/// differences' own error -- truncation, taken as 1e-5 (velocity) and 1e-4
/// (acceleration) of the derivative's scale over the run, and round-off: each value of
/// the stencil is off by about eps (|x| + |t v|) (the expression's rounding and that of
/// t), amplified by the stencil's weights, (1 + 8 + 8 + 1) / (12 h) and
/// (1 + 16 + 30 + 16 + 1) / (12 h^2). The scale of the acceleration includes v / T
/// (T: the run's duration), so that a true acceleration of 0 does not make the
/// tolerance collapse to round-off alone.
void check_driver_derivatives(const CaseDefinition& definition, const ExpressionContext& expressions,
                              const NodeReader& section) {
  const std::vector<NodeReader> items = section.items();
  const double h = TimeFunction::difference_step, eps = std::numeric_limits<double>::epsilon();
  constexpr double round_off_margin = 4.0;  // the bound is a worst case: 1.14e-6 seen where it gives 8.2e-6
  for (std::size_t d = 0; d < definition.drivers.size(); ++d) {
    const NodeReader& item = items[d];
    if (!item.has("velocity")) continue;
    const TimeFunction differenced(definition.drivers[d].name, item["position"].node().scalar, std::nullopt,
                                   std::nullopt, expressions.parameters());
    const double t0 = definition.solver.t_start, t1 = definition.solver.t_end, duration = t1 - t0;
    std::vector<double> times;
    std::vector<DriverMotion> given, reference;
    double scale_v = 0.0, scale_a = 0.0;
    for (int k = 0; k <= 20; ++k) {
      times.push_back(t0 + duration * k / 20.0);
      given.push_back(definition.drivers[d].motion(times.back()));
      reference.push_back(differenced(times.back()));
      scale_v = std::max(scale_v, std::abs(given.back().velocity));
      scale_a = std::max(scale_a, std::abs(given.back().acceleration));
    }
    scale_a = std::max(scale_a, scale_v / duration);
    for (std::size_t k = 0; k < times.size(); ++k) {
      const double value_error =
          round_off_margin * eps * (std::abs(reference[k].position) + std::abs(times[k] * given[k].velocity));
      const double tolerance_v = 1e-5 * scale_v + value_error * 18.0 / (12.0 * h);
      const double tolerance_a = 1e-4 * scale_a + value_error * 64.0 / (12.0 * h * h);
      const double error_v = std::abs(given[k].velocity - reference[k].velocity);
      const double error_a = std::abs(given[k].acceleration - reference[k].acceleration);
      if (!(error_v <= tolerance_v))
        item["velocity"].fail(fmt::format("a velocity that differs from d(position)/dt by {:.3g} at t = {:g} s "
                                          "(tolerance {:.3g})",
                                          error_v, times[k], tolerance_v),
                              "the exact time derivative of position");
      if (!(error_a <= tolerance_a))
        item["acceleration"].fail(fmt::format("an acceleration that differs from d2(position)/dt2 by {:.3g} at t = "
                                              "{:g} s (tolerance {:.3g})",
                                              error_a, times[k], tolerance_a),
                                  "the exact second time derivative of position");
    }
  }
}

}  // namespace

void check_motions_over_run(const CaseDefinition& definition, const ExpressionContext& expressions,
                            const std::optional<NodeReader>& drivers) {
  check_expressions_over_run(definition, expressions, drivers);
  if (drivers) check_driver_derivatives(definition, expressions, *drivers);
}

}  // namespace heavesim
