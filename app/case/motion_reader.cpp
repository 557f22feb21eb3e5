// Reads and checks prescribed motions f(t) (docs/case-format.md, "drivers[i]").
#include "app/case/motion_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "app/case/motion_table.hpp"
#include "hydro/data_error.hpp"
#include "hydro/data_file.hpp"
#include "kernel/math/numerical_error.hpp"

namespace heavesim {

namespace {

const char* const motion_expectation = "an expression of t such as 8 + 3*sin(t)";

/// The driver's `table`: a CSV file, its path relative to the file holding the key.
std::shared_ptr<const TimeFunction> read_table(const NodeReader& item, const std::string& name) {
  const NodeReader key = item["table"];
  for (const char* other : {"position", "velocity", "acceleration"})
    if (item.has(other))
      item[other].fail(fmt::format("'{}' beside 'table'", other),
                       "either a table or a position expression (a table's derivatives are the spline's)");
  const std::string text = key.text();
  std::filesystem::path path(text);
  if (path.is_relative()) path = std::filesystem::path(key.location().file).parent_path() / path;
  const std::string csv_expectation = "a CSV file relative to the case file: a header line, then rows 'time [s], value'";
  if (const std::string problem = hydro::unreadable_file(path.string(), hydro::max_data_file_bytes); !problem.empty())
    key.fail(fmt::format("'{}', {} ({})", text, problem, path.string()), csv_expectation);
  try {
    return std::make_shared<const TimeFunction>(
        name, std::make_shared<const MotionTable>(MotionTable::read_csv(path.lexically_normal().string())));
  } catch (const hydro::DataError& error) {
    const std::string where = error.line() > 0 ? fmt::format("{}:{}", error.file(), error.line()) : error.file();
    key.fail(error.found() + " (in " + where + ")", error.expected());
  }
}

}  // namespace

std::shared_ptr<const TimeFunction> read_motion(const NodeReader& item, const std::string& name,
                                                const ExpressionContext& expressions) {
  if (item.has("table")) return read_table(item, name);
  auto expression = [&](const std::string& key) -> std::optional<std::string> {
    auto node = item.optional(key);
    if (!node) return std::nullopt;
    if (!node->node().is_scalar()) node->fail(motion_expectation);
    // Each expression alone, so that an error points at the right key; muParser's
    // message gives the column ("Unexpected end of expression at position 11").
    try {
      TimeFunction(name, node->node().scalar, std::nullopt, std::nullopt, expressions.parameters());
    } catch (const std::invalid_argument& e) {
      node->fail(node->node().describe() + " (" + e.what() + ")", motion_expectation);
    }
    return node->node().scalar;
  };
  // Required (or a table): a missing key, or one left empty (`position:` with nothing
  // after it is YAML's null), is reported at that key.
  const std::optional<std::string> position = expression("position");
  if (!position) item["position"].fail(motion_expectation);
  const std::optional<std::string> velocity = expression("velocity"), acceleration = expression("acceleration");
  if (velocity.has_value() != acceleration.has_value())
    item[velocity ? "velocity" : "acceleration"].fail("only one of velocity and acceleration",
                                                      "both (the exact derivatives of position) or neither");
  return std::make_shared<const TimeFunction>(name, *position, velocity, acceleration, expressions.parameters());
}

std::shared_ptr<const TimeFunction> read_time_expression(const NodeReader& key, const std::string& name,
                                                         const ExpressionContext& expressions,
                                                         const std::string& owner, const std::string& expected) {
  if (!key.node().is_scalar()) key.fail(expected);
  try {
    return std::make_shared<const TimeFunction>(name, key.node().scalar, std::nullopt, std::nullopt,
                                                expressions.parameters(), owner);
  } catch (const std::invalid_argument& e) {
    key.fail(key.node().describe() + " (" + e.what() + ")", expected);
  }
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
/// (sqrt(1 - t) on a 2 s run), or, `with_derivatives`, whose first two time
/// derivatives are not (sqrt(t) at t = 0): bad input, found before running rather than
/// reported as a numerical failure when the run reaches it.
void check_finite_over_run(const TimeFunction& function, bool with_derivatives, const std::vector<double>& times,
                           const CaseDefinition& definition, const std::string& key_path) {
  try {
    for (const double t : times)
      if (with_derivatives)
        function(t);
      else
        function.position(t);
  } catch (const NumericalError& error) {
    throw definition.error_at(key_path, fmt::format("{} at t = {:.6g} s", error.what(), error.time()),
                              fmt::format("an expression of t that is finite{} over the whole run, t = {:g} .. {:g} s",
                                          with_derivatives ? ", with its first two time derivatives," : "",
                                          definition.solver.t_start, definition.solver.t_end));
  }
}

/// A driver's given `velocity` and `acceleration` must be the derivatives of its
/// position (a typo in `velocity` would otherwise fight the position constraint):
/// compared with the exact derivatives at every check time. Both sides are exact
/// formulas evaluated in double precision, so they differ by round-off only: a few
/// units of 2.2e-16 per operation, times the magnification of cancelling terms. The
/// tolerance, 1e-9 of the derivative's largest magnitude over the run (for the
/// acceleration at least that of velocity/duration, so that a true acceleration of 0
/// does not reduce it to nothing), leaves a factor of 4e6 over one rounding for such
/// magnification; a wrong derivative is off by its own size.
void check_given_derivatives(const TimeFunction& given, const TimeFunction& exact, const NodeReader& item,
                             const std::vector<double>& times, double duration) {
  constexpr double relative_tolerance = 1e-9;
  std::vector<DriverMotion> stated, reference;
  double scale_v = 0.0, scale_a = 0.0;
  for (const double t : times) {
    stated.push_back(given(t));
    reference.push_back(exact(t));
    scale_v = std::max({scale_v, std::abs(stated.back().velocity), std::abs(reference.back().velocity)});
    scale_a = std::max({scale_a, std::abs(stated.back().acceleration), std::abs(reference.back().acceleration)});
  }
  scale_a = std::max(scale_a, scale_v / duration);
  const double tolerance_v = relative_tolerance * scale_v, tolerance_a = relative_tolerance * scale_a;
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double error_v = std::abs(stated[k].velocity - reference[k].velocity);
    const double error_a = std::abs(stated[k].acceleration - reference[k].acceleration);
    if (!(error_v <= tolerance_v))
      item["velocity"].fail(fmt::format("a velocity that differs from d(position)/dt by {:.3g} at t = {:g} s "
                                        "(tolerance {:.3g}: 1e-9 of the largest velocity over the run)",
                                        error_v, times[k], tolerance_v),
                            "the exact time derivative of position");
    if (!(error_a <= tolerance_a))
      item["acceleration"].fail(fmt::format("an acceleration that differs from d2(position)/dt2 by {:.3g} at t = "
                                            "{:g} s (tolerance {:.3g}: 1e-9 of the largest acceleration over the run)",
                                            error_a, times[k], tolerance_a),
                                "the exact second time derivative of position");
  }
}

/// A driver's table must cover the run: beyond it the spline's end cubics would be
/// extrapolated, which no measurement supports.
void check_table_covers_run(const TimeFunction& function, const CaseDefinition& definition, const NodeReader& key) {
  const auto [first, last] = function.time_range();
  const double t0 = definition.solver.t_start, t1 = definition.solver.t_end;
  if (t0 < first || t1 > last)
    key.fail(fmt::format("a table of t = {:g} .. {:g} s for a run of t = {:g} .. {:g} s", first, last, t0, t1),
             "a table whose times cover the whole run (solver.t_start .. solver.t_end)");
}

}  // namespace

void check_motions_over_run(const CaseDefinition& definition, const ExpressionContext& expressions,
                            const std::optional<NodeReader>& drivers) {
  const std::vector<double> times = expression_check_times(definition);
  if (drivers) {
    const std::vector<NodeReader> items = drivers->items();
    for (std::size_t d = 0; d < definition.drivers.size(); ++d) {
      const NodeReader& item = items[d];
      const std::string& name = definition.drivers[d].name;
      if (item.has("table")) {
        check_table_covers_run(*read_motion(item, name, expressions), definition, item["table"]);
        continue;
      }
      // Each expression alone, so that a failure is reported at its key; the
      // position with its exact derivatives.
      for (const char* key : {"position", "velocity", "acceleration"}) {
        const std::optional<NodeReader> expression = item.optional(key);
        if (!expression) continue;
        const TimeFunction alone(name, expression->node().scalar, std::nullopt, std::nullopt, expressions.parameters());
        check_finite_over_run(alone, std::string(key) == "position", times, definition, expression->path());
      }
      if (item.has("velocity")) {
        const TimeFunction exact(name, item["position"].node().scalar, std::nullopt, std::nullopt,
                                 expressions.parameters());
        const TimeFunction given(name, item["position"].node().scalar, item["velocity"].node().scalar,
                                 item["acceleration"].node().scalar, expressions.parameters());
        check_given_derivatives(given, exact, item, times, definition.solver.t_end - definition.solver.t_start);
      }
    }
  }
  for (const ForceDefinition& force : definition.forces) {
    const std::string& path = definition.item_paths.at(force.name);
    if (const auto* torque = std::get_if<JointTorqueDefinition>(&force.kind))
      check_finite_over_run(*torque->torque, false, times, definition, path + ".torque");
    if (const auto* load = std::get_if<BodyLoadDefinition>(&force.kind))
      for (const auto& [key, components] : {std::pair{"force", &load->force}, std::pair{"moment", &load->moment}})
        for (int k = 0; k < 3; ++k)
          if ((*components)[k])
            check_finite_over_run(*(*components)[k], false, times, definition, fmt::format("{}.{}[{}]", path, key, k));
  }
}

}  // namespace heavesim
