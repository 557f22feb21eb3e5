// The expression parser (muParser behind ExpressionContext and TimeFunction).
// The bytes are lines: "name = expression" defines a parameter (ExpressionContext::define
// with the value of ExpressionContext::evaluate), any other line is evaluated; the last
// line is also made a TimeFunction with the parameters, evaluated at a few times.
// The contract (app/case/expression.hpp, time_function.hpp): a bad expression or name is
// std::invalid_argument, a value that is not finite during a run a NumericalError.
// Anything else is a finding.
#include <stdexcept>

#include "app/case/expression.hpp"
#include "app/case/time_function.hpp"
#include "fuzz/fuzz_support.hpp"
#include "kernel/math/numerical_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace heavesim;
  const std::vector<std::string_view> lines = fuzz::lines(fuzz::as_text(data, size));
  ExpressionContext context;
  for (std::string_view line : lines) {
    try {
      const std::size_t equals = line.find('=');
      // "a == b" and "a <= b" are comparisons, not definitions.
      const bool definition = equals != std::string_view::npos && equals > 0 && equals + 1 < line.size() &&
                              line[equals + 1] != '=' && line.find_first_of("<>!=") == equals;
      if (definition) {
        std::string name(line.substr(0, equals));
        while (!name.empty() && name.back() == ' ') name.pop_back();
        context.define(name, context.evaluate(std::string(line.substr(equals + 1))));
      } else {
        context.evaluate(std::string(line));
      }
    } catch (const std::invalid_argument&) {
    } catch (...) {
      fuzz::report_unexpected_exception("fuzz_expression");
    }
  }
  if (lines.empty()) return 0;
  try {
    const TimeFunction function("fuzz", std::string(lines.back()), std::nullopt, std::nullopt, context.parameters());
    function.position_uses_time();
    for (const double t : {0.0, 0.25, -3.0, 1e6}) function(t);
  } catch (const std::invalid_argument&) {
  } catch (const NumericalError&) {
  } catch (...) {
    fuzz::report_unexpected_exception("fuzz_expression");
  }
  return 0;
}
