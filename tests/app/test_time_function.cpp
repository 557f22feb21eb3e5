// Exact time derivatives of prescribed motions (app/case/time_function.hpp): every
// function of case expressions, the motion helpers, the conditional, parameters and
// nested compositions, against closed-form derivatives written here; and tabulated
// motion (app/case/motion_table.hpp) against polynomials the spline must reproduce and
// the spline's own error bound.
//
// Tolerance 1e-13 relative (to max(1, |reference|)): both sides are a handful of
// double operations on the same values, so they differ by a few roundings (2.2e-16
// each) times the condition of the formula; 1e-13 leaves a factor of ~500 for that.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>

#include <fmt/format.h>

#include "app/case/coordinate_expression.hpp"
#include "app/case/motion_table.hpp"
#include "app/case/time_function.hpp"
#include "app/case/case_definition.hpp"
#include "app/run/simulation_run.hpp"
#include "app/scene/scene.hpp"
#include "hydro/data_error.hpp"
#include "kernel/math/numerical_error.hpp"
#include "tests/test_support.hpp"

namespace heavesim {
namespace {

struct ClosedForm {
  std::string expression;
  std::function<DriverMotion(double t)> reference;  // f, f', f'' written by hand
  std::vector<double> times;
};

void expect_exact(const ClosedForm& form, const std::map<std::string, double>& parameters = {}) {
  SCOPED_TRACE(form.expression);
  const TimeFunction function("test", form.expression, std::nullopt, std::nullopt, parameters);
  for (const double t : form.times) {
    SCOPED_TRACE("t = " + std::to_string(t));
    const DriverMotion exact = function(t), reference = form.reference(t);
    constexpr double tolerance = 1e-13;
    EXPECT_NEAR(exact.position, reference.position, tolerance * std::max(1.0, std::abs(reference.position)));
    EXPECT_NEAR(exact.velocity, reference.velocity, tolerance * std::max(1.0, std::abs(reference.velocity)));
    EXPECT_NEAR(exact.acceleration, reference.acceleration,
                tolerance * std::max(1.0, std::abs(reference.acceleration)));
    EXPECT_EQ(function.position(t), exact.position);  // muParser's value and the Taylor value: the same operations
  }
}

const std::vector<double> test_times{0.0, 0.37, 1.0, 1.9};  // s

TEST(TimeFunction, EveryFunctionHasItsExactDerivatives) {
  // Inner argument u = 0.3 + 0.2 t (u' = 0.2, u'' = 0) so that the chain rule is exercised.
  const double a = 0.2;
  auto u = [](double t) { return 0.3 + 0.2 * t; };
  const std::vector<ClosedForm> forms{
      {"sin(0.3 + 0.2*t)", [&](double t) { return DriverMotion{std::sin(u(t)), a * std::cos(u(t)), -a * a * std::sin(u(t))}; }, test_times},
      {"cos(0.3 + 0.2*t)", [&](double t) { return DriverMotion{std::cos(u(t)), -a * std::sin(u(t)), -a * a * std::cos(u(t))}; }, test_times},
      {"tan(0.3 + 0.2*t)", [&](double t) {
         const double c = std::cos(u(t));
         return DriverMotion{std::tan(u(t)), a / (c * c), 2 * a * a * std::tan(u(t)) / (c * c)};
       }, test_times},
      {"asin(0.3 + 0.2*t)", [&](double t) {
         const double x = u(t);
         return DriverMotion{std::asin(x), a / std::sqrt(1 - x * x), a * a * x / std::pow(1 - x * x, 1.5)};
       }, test_times},
      {"acos(0.3 + 0.2*t)", [&](double t) {
         const double x = u(t);
         return DriverMotion{std::acos(x), -a / std::sqrt(1 - x * x), -a * a * x / std::pow(1 - x * x, 1.5)};
       }, test_times},
      {"atan(0.3 + 0.2*t)", [&](double t) {
         const double x = u(t);
         return DriverMotion{std::atan(x), a / (1 + x * x), -2 * a * a * x / std::pow(1 + x * x, 2)};
       }, test_times},
      {"atan2(t, 2)", [](double t) {  // = atan(t/2)
         return DriverMotion{std::atan(t / 2), 2 / (4 + t * t), -4 * t / std::pow(4 + t * t, 2)};
       }, test_times},
      {"atan2(2, 1 + t)", [](double t) {  // = pi/2 - atan((1 + t)/2) for 1 + t > 0
         const double x = 1 + t;
         return DriverMotion{std::numbers::pi / 2 - std::atan(x / 2), -2 / (4 + x * x), 4 * x / std::pow(4 + x * x, 2)};
       }, test_times},
      {"sinh(0.3 + 0.2*t)", [&](double t) { return DriverMotion{std::sinh(u(t)), a * std::cosh(u(t)), a * a * std::sinh(u(t))}; }, test_times},
      {"cosh(0.3 + 0.2*t)", [&](double t) { return DriverMotion{std::cosh(u(t)), a * std::sinh(u(t)), a * a * std::cosh(u(t))}; }, test_times},
      {"tanh(0.3 + 0.2*t)", [&](double t) {
         const double c = std::cosh(u(t));
         return DriverMotion{std::tanh(u(t)), a / (c * c), -2 * a * a * std::tanh(u(t)) / (c * c)};
       }, test_times},
      {"asinh(0.3 + 0.2*t)", [&](double t) {
         const double x = u(t);
         return DriverMotion{std::asinh(x), a / std::sqrt(x * x + 1), -a * a * x / std::pow(x * x + 1, 1.5)};
       }, test_times},
      {"acosh(1.3 + 0.2*t)", [&](double t) {
         const double x = 1 + u(t);
         return DriverMotion{std::acosh(x), a / std::sqrt(x * x - 1), -a * a * x / std::pow(x * x - 1, 1.5)};
       }, test_times},
      {"atanh(0.3 + 0.2*t)", [&](double t) {
         const double x = u(t);
         return DriverMotion{std::atanh(x), a / (1 - x * x), 2 * a * a * x / std::pow(1 - x * x, 2)};
       }, test_times},
      {"exp(0.3 + 0.2*t)", [&](double t) {
         const double e = std::exp(u(t));
         return DriverMotion{e, a * e, a * a * e};
       }, test_times},
      {"ln(0.3 + 0.2*t)", [&](double t) { return DriverMotion{std::log(u(t)), a / u(t), -a * a / (u(t) * u(t))}; }, test_times},
      {"log(0.3 + 0.2*t)", [&](double t) { return DriverMotion{std::log(u(t)), a / u(t), -a * a / (u(t) * u(t))}; }, test_times},
      {"log10(0.3 + 0.2*t)", [&](double t) {
         const double l = std::log(10.0);
         return DriverMotion{std::log10(u(t)), a / (u(t) * l), -a * a / (u(t) * u(t) * l)};
       }, test_times},
      {"log2(0.3 + 0.2*t)", [&](double t) {
         const double l = std::log(2.0);
         return DriverMotion{std::log2(u(t)), a / (u(t) * l), -a * a / (u(t) * u(t) * l)};
       }, test_times},
      {"sqrt(0.3 + 0.2*t)", [&](double t) {
         return DriverMotion{std::sqrt(u(t)), a / (2 * std::sqrt(u(t))), -a * a / (4 * std::pow(u(t), 1.5))};
       }, test_times},
      {"deg(30*t)", [](double t) { return DriverMotion{t * std::numbers::pi / 6, std::numbers::pi / 6, 0}; }, test_times},
      {"rad(t)", [](double t) { return DriverMotion{t * 180 / std::numbers::pi, 180 / std::numbers::pi, 0}; }, test_times},
      {"-(t*t) + +t", [](double t) { return DriverMotion{-t * t + t, -2 * t + 1, -2}; }, test_times},
      {"(1 + t)/(2 + t^2)", [](double t) {  // quotient rule written out
         const double n = 1 + t, d = 2 + t * t;
         const double f1 = (d - n * 2 * t) / (d * d);  // = (2 - 2t - t^2)/d^2
         const double f2 = ((-2 - 2 * t) * d * d - (2 - 2 * t - t * t) * 2 * d * 2 * t) / std::pow(d, 4);
         return DriverMotion{n / d, f1, f2};
       }, test_times},
  };
  for (const ClosedForm& form : forms) expect_exact(form);
}

TEST(TimeFunction, PowersAreExactIncludingIntegerPowersAtZero) {
  const std::vector<ClosedForm> forms{
      {"(1 + t)^2.5", [](double t) {
         return DriverMotion{std::pow(1 + t, 2.5), 2.5 * std::pow(1 + t, 1.5), 3.75 * std::pow(1 + t, 0.5)};
       }, test_times},
      {"t^2", [](double t) { return DriverMotion{t * t, 2 * t, 2}; }, test_times},
      {"t^3", [](double t) { return DriverMotion{t * t * t, 3 * t * t, 6 * t}; }, test_times},
      {"t^1", [](double t) { return DriverMotion{t, 1, 0}; }, test_times},
      {"t^0", [](double) { return DriverMotion{1, 0, 0}; }, test_times},
      {"2^t", [](double t) {
         const double l = std::log(2.0), p = std::pow(2.0, t);
         return DriverMotion{p, p * l, p * l * l};
       }, test_times},
      {"(1 + t)^(1 + t)", [](double t) {  // x^x: (x^x)' = x^x (ln x + 1), (x^x)'' = x^x ((ln x + 1)^2 + 1/x)
         const double x = 1 + t, p = std::pow(x, x), l = std::log(x) + 1;
         return DriverMotion{p, p * l, p * (l * l + 1 / x)};
       }, test_times},
  };
  for (const ClosedForm& form : forms) expect_exact(form);
}

TEST(TimeFunction, NonSmoothFunctionsTakeTheActiveBranch) {
  const std::vector<double> either_side{0.2, 0.7, 1.3, 1.9};
  const std::vector<ClosedForm> forms{
      {"abs(t - 1)", [](double t) { return t < 1 ? DriverMotion{1 - t, -1, 0} : DriverMotion{t - 1, 1, 0}; }, either_side},
      {"sign(t - 1)", [](double t) { return DriverMotion{t < 1 ? -1.0 : 1.0, 0, 0}; }, either_side},
      {"rint(3*t)", [](double t) { return DriverMotion{std::floor(3 * t + 0.5), 0, 0}; }, either_side},
      {"min(t^2, 2 - t)", [](double t) {
         return t * t < 2 - t ? DriverMotion{t * t, 2 * t, 2} : DriverMotion{2 - t, -1, 0};
       }, either_side},
      {"max(t^2, 2 - t)", [](double t) {
         return t * t > 2 - t ? DriverMotion{t * t, 2 * t, 2} : DriverMotion{2 - t, -1, 0};
       }, either_side},
      {"sum(t, t^2, 3)", [](double t) { return DriverMotion{t + t * t + 3, 1 + 2 * t, 2}; }, either_side},
      {"avg(t, t^3)", [](double t) { return DriverMotion{(t + t * t * t) / 2, (1 + 3 * t * t) / 2, 3 * t}; }, either_side},
      {"t < 1 ? t^2 : 2*t - 1", [](double t) { return t < 1 ? DriverMotion{t * t, 2 * t, 2} : DriverMotion{2 * t - 1, 2, 0}; }, either_side},
      {"t > 0.5 && t < 1.5 ? sin(t) : 0", [](double t) {
         return t > 0.5 && t < 1.5 ? DriverMotion{std::sin(t), std::cos(t), -std::sin(t)} : DriverMotion{0, 0, 0};
       }, either_side},
  };
  for (const ClosedForm& form : forms) expect_exact(form);
}

TEST(TimeFunction, HelpersHaveTheirPolynomialsDerivatives) {
  // Between x0 = 0.5 and x1 = 1.5 (d = t - 0.5, span 1), from h0 = 2 to h1 = 5 (a = 3).
  const std::vector<double> across{0.1, 0.5, 0.8, 1.0, 1.25, 1.5, 1.9};
  auto inside = [](double t) { return t > 0.5 && t < 1.5; };
  const std::vector<ClosedForm> forms{
      {"step(t, 0.5, 2, 1.5, 5)", [&](double t) {
         const double d = t - 0.5;
         if (!inside(t)) return DriverMotion{t <= 0.5 ? 2.0 : 5.0, 0, 0};
         return DriverMotion{2 + 3 * d * d * (3 - 2 * d), 3 * 6 * d * (1 - d), 3 * (6 - 12 * d)};
       }, across},
      {"step5(t, 0.5, 2, 1.5, 5)", [&](double t) {
         const double d = t - 0.5;
         if (!inside(t)) return DriverMotion{t <= 0.5 ? 2.0 : 5.0, 0, 0};
         return DriverMotion{2 + 3 * d * d * d * (10 - 15 * d + 6 * d * d), 3 * 30 * d * d * (1 - d) * (1 - d),
                             3 * 60 * d * (1 - d) * (1 - 2 * d)};
       }, across},
      {"ramp(t, 0.5, 1.5)", [&](double t) {
         if (!inside(t)) return DriverMotion{t <= 0.5 ? 0.0 : 1.0, 0, 0};
         return DriverMotion{t - 0.5, 1, 0};
       }, across},
      {"smoothstep(t, 0.5, 1.5)", [&](double t) {
         const double d = t - 0.5;
         if (!inside(t)) return DriverMotion{t <= 0.5 ? 0.0 : 1.0, 0, 0};
         return DriverMotion{d * d * d * (10 - 15 * d + 6 * d * d), 30 * d * d * (1 - d) * (1 - d),
                             60 * d * (1 - d) * (1 - 2 * d)};
       }, across},
      // A helper as an argument to another: the chain rule through the helper.
      {"sin(step5(t, 0.5, 0, 1.5, 1))", [&](double t) {
         const double d = t - 0.5;
         if (!inside(t)) return DriverMotion{std::sin(t <= 0.5 ? 0.0 : 1.0), 0, 0};
         const double h = d * d * d * (10 - 15 * d + 6 * d * d), h1 = 30 * d * d * (1 - d) * (1 - d),
                      h2 = 60 * d * (1 - d) * (1 - 2 * d);
         return DriverMotion{std::sin(h), std::cos(h) * h1, std::cos(h) * h2 - std::sin(h) * h1 * h1};
       }, across},
  };
  for (const ClosedForm& form : forms) expect_exact(form);
}

TEST(TimeFunction, NestedCompositionsWithParameters) {
  const std::map<std::string, double> parameters{{"A", 2.0}, {"w", 3.0}, {"z0", 8.0}};
  expect_exact({"z0 + A*sin(w*t)", [](double t) {
                  return DriverMotion{8 + 2 * std::sin(3 * t), 6 * std::cos(3 * t), -18 * std::sin(3 * t)};
                }, test_times},
               parameters);
  // exp(sin(w t)): f' = w cos e^s, f'' = w^2 e^s (cos^2 - sin).
  expect_exact({"exp(sin(w*t))", [](double t) {
                  const double s = std::sin(3 * t), c = std::cos(3 * t), e = std::exp(s);
                  return DriverMotion{e, 3 * c * e, 9 * e * (c * c - s)};
                }, test_times},
               parameters);
  // sqrt(1 + (A t)^2): f' = A^2 t / f, f'' = A^2 / f^3.
  expect_exact({"sqrt(1 + (A*t)^2)", [](double t) {
                  const double f = std::sqrt(1 + 4 * t * t);
                  return DriverMotion{f, 4 * t / f, 4 / (f * f * f)};
                }, test_times},
               parameters);
}

TEST(TimeFunction, GivenDerivativesAreUsedAsWritten) {
  const TimeFunction function("test", "sin(t)", std::string("cos(t)"), std::string("-sin(t)"), {});
  const DriverMotion motion = function(0.7);
  EXPECT_EQ(motion.velocity, std::cos(0.7));
  EXPECT_EQ(motion.acceleration, -std::sin(0.7));
}

TEST(TimeFunction, SyntaxErrorGivesMuParsersColumn) {
  try {
    TimeFunction("test", "8 + 3*sin(t", std::nullopt, std::nullopt, {});
    FAIL() << "accepted";
  } catch (const std::invalid_argument& error) {
    // muParser finds the missing ')' at the end, index 11 (0-based) of the 11 characters.
    EXPECT_NE(std::string(error.what()).find("Missing parenthesis at position 11"), std::string::npos) << error.what();
  }
  EXPECT_THROW(TimeFunction("test", "t = 3", std::nullopt, std::nullopt, {}), std::invalid_argument);
  EXPECT_THROW(TimeFunction("test", "1, t", std::nullopt, std::nullopt, {}), std::invalid_argument);
}

TEST(TimeFunction, InfiniteDerivativeIsANumericalError) {
  const TimeFunction function("test", "sqrt(t)", std::nullopt, std::nullopt, {});
  EXPECT_EQ(function.position(0.0), 0.0);
  EXPECT_THROW(function(0.0), NumericalError);
}

// Tabulated motion.

TEST(MotionTable, SplineThroughSamplesOfACubicReproducesIt) {
  // p(t) = 1 + 2 t - 0.5 t^2 + 0.1 t^3 on uneven samples: a cubic lies in the spline
  // space, so interpolation returns it exactly (to round-off in the collocation solve).
  auto p = [](double t) {
    return DriverMotion{1 + 2 * t - 0.5 * t * t + 0.1 * t * t * t, 2 - t + 0.3 * t * t, -1 + 0.6 * t};
  };
  std::vector<double> sample_times{0.0, 0.3, 0.45, 1.0, 1.7, 2.0, 2.2, 3.1, 3.5, 4.0};
  std::vector<double> values;
  for (const double t : sample_times) values.push_back(p(t).position);
  const MotionTable table(sample_times, values);
  for (double t = 0.0; t <= 4.0; t += 0.0625) {
    SCOPED_TRACE(t);
    const DriverMotion spline = table(t), exact = p(t);
    // Round-off of the collocation solve and of the basis recursion, magnified by the
    // time scaling 1/T^k (T = 4 s): 1e-13 of the values' scale (~5).
    EXPECT_NEAR(spline.position, exact.position, 1e-12);
    EXPECT_NEAR(spline.velocity, exact.velocity, 1e-12);
    EXPECT_NEAR(spline.acceleration, exact.acceleration, 1e-11);
  }
}

TEST(MotionTable, MeasuredHeaveLikeRecordWithinTheSplinesErrorBound) {
  // A heave record sampled at 10 Hz for 60 s: two swell components. Inside the record the
  // cubic spline's error is bounded by Hall & Meyer's constants (J. Approx. Theory 16,
  // 1976) for the complete spline, h^4 |f''''| 5/384, h^3 |f''''| / 24, h^2 |f''''| 3/8,
  // which the not-a-knot spline meets away from its ends (de Boor ch. V); a factor 2 covers
  // the end effect's decay over the ten samples skipped at each end.
  const double a1 = 1.2, w1 = 2 * std::numbers::pi / 9.0, a2 = 0.4, w2 = 2 * std::numbers::pi / 5.3, h = 0.1;
  auto heave = [&](double t) {
    return DriverMotion{a1 * std::sin(w1 * t) + a2 * std::sin(w2 * t + 0.4),
                        a1 * w1 * std::cos(w1 * t) + a2 * w2 * std::cos(w2 * t + 0.4),
                        -a1 * w1 * w1 * std::sin(w1 * t) - a2 * w2 * w2 * std::sin(w2 * t + 0.4)};
  };
  const double fourth = a1 * std::pow(w1, 4) + a2 * std::pow(w2, 4);  // max |f''''|
  std::vector<double> sample_times, values;
  for (int i = 0; i <= 600; ++i) {
    sample_times.push_back(i * h);
    values.push_back(heave(i * h).position);
  }
  const MotionTable table(sample_times, values);
  double worst[3] = {0, 0, 0};
  for (double t = 1.0; t <= 59.0; t += 0.0137) {
    const DriverMotion spline = table(t), exact = heave(t);
    worst[0] = std::max(worst[0], std::abs(spline.position - exact.position));
    worst[1] = std::max(worst[1], std::abs(spline.velocity - exact.velocity));
    worst[2] = std::max(worst[2], std::abs(spline.acceleration - exact.acceleration));
  }
  EXPECT_LT(worst[0], 2 * 5.0 / 384 * std::pow(h, 4) * fourth);
  EXPECT_LT(worst[1], 2 * std::pow(h, 3) / 24 * fourth);
  EXPECT_LT(worst[2], 2 * 3.0 / 8 * h * h * fourth);
  // At the samples the spline interpolates.
  for (int i = 0; i <= 600; i += 37) EXPECT_NEAR(table(sample_times[i]).position, values[i], 1e-13);
}

std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  std::ofstream(path) << text;
  return path;
}

TEST(MotionTable, CsvProblemsAreReportedAtTheirLine) {
  struct Bad {
    std::string text;
    int line;
    std::string found;
  };
  for (const Bad& bad : {Bad{"t,z\n0,0\n1,1\n2,x\n3,3\n", 4, "'x' in column 2"},
                         Bad{"t,z\n0,0\n1,1\n1,2\n3,3\n", 4, "time 1 s after 1 s (line 3)"},
                         Bad{"t,z\n0,0\n1,nan\n2,2\n3,3\n", 3, "not finite"},
                         Bad{"t,z\n0,0\n1,1,1\n2,2\n3,3\n", 3, "not two comma-separated columns"},
                         Bad{"t,z\n0,0\n1,1\n2,2\n", 4, "3 rows"}}) {
    SCOPED_TRACE(bad.text);
    const std::string path = write_file("heavesim_motion_table.csv", bad.text);
    try {
      MotionTable::read_csv(path);
      FAIL() << "accepted";
    } catch (const hydro::DataError& error) {
      EXPECT_EQ(error.line(), bad.line);
      EXPECT_NE(error.found().find(bad.found), std::string::npos) << error.found();
    }
  }
}

TEST(MotionTable, DriverFollowsATableOfACubicAndNeedsItsForce) {
  // A 2 kg cart on a rail along x (gravity along -z), driven by a table sampling
  // x(t) = 0.1 t + 0.05 t^2 - 0.01 t^3 at uneven times: the spline is that cubic, so the
  // cart follows it and the driver's force is m x''(t) = 2 (0.1 - 0.06 t) N.
  auto x = [](double t) { return 0.1 * t + 0.05 * t * t - 0.01 * t * t * t; };
  std::string csv = "time_s, x_m\n";
  for (const double t : {0.0, 0.2, 0.5, 0.6, 1.1, 1.5, 2.0, 2.4, 3.0}) csv += fmt::format("{:.17g}, {:.17g}\n", t, x(t));
  write_file("heavesim_table_cubic.csv", csv);
  const std::string path = write_file("heavesim_table_cubic.yaml",
                                      "bodies:\n"
                                      "  - {name: cart, mass: 2.0, inertia: [0.1, 0.1, 0.1]}\n"
                                      "joints:\n"
                                      "  - {name: rail, type: prismatic, parent: ground, child: cart, axis: [1, 0, 0]}\n"
                                      "drivers:\n"
                                      "  - {name: pusher, joint: rail, table: heavesim_table_cubic.csv}\n"
                                      "solver: {integrator: dopri5, rtol: 1e-10, atol: 1e-12, t_end: 2}\n"
                                      "output: {interval: 0.1}\n");
  const CaseDefinition definition = load_case(path);
  Scene scene = build_scene(definition);
  const int rail = scene.model->joint_index("rail");
  auto integrator = make_integrator(definition.solver.integrator, *scene.system);
  double position_error = 0.0, force_error = 0.0;
  int samples = 0;
  run_simulation(scene, definition.solver, definition.output.interval, *integrator, [&](double t, const VectorX& y) {
    scene.system->evaluate(t, y, true);
    position_error = std::max(position_error, std::abs(y[scene.model->joints[rail].q_index] - x(t)));
    force_error = std::max(force_error, std::abs(scene.system->data().constraint_multipliers[0] - 2 * (0.1 - 0.06 * t)));
    ++samples;
    return true;
  });
  EXPECT_EQ(samples, 21);
  // The spline equals the cubic to ~1e-15; the rest is the integrator's tolerance.
  EXPECT_LT(position_error, 1e-9);
  EXPECT_LT(force_error, 1e-9);
}

// User-defined constraints Phi(x, t) = 0 as expressions of coordinates.

TEST(CoordinateExpression, CamConstraintGradientAndBiasAgainstClosedForm) {
  // Phi = s - 0.2 sin(theta) - 0.01 t: Phi_theta = -0.2 cos(theta), Phi_s = 1, Phi_t = -0.01;
  // the only second derivative is Phi_theta,theta = 0.2 sin(theta).
  const CoordinateExpression cam("s - 0.2*sin(theta) - 0.01*t", {"theta", "s"}, {});
  for (const double theta : {0.0, 0.7, 2.5, -1.2}) {
    const double x[] = {theta, 0.13}, rates[] = {3.0, -0.4}, t = 0.9;
    double gradient[2], time_partial = 0.0;
    const double phi = cam.gradient(x, t, gradient, time_partial);
    EXPECT_NEAR(phi, 0.13 - 0.2 * std::sin(theta) - 0.009, 1e-15);
    EXPECT_NEAR(gradient[0], -0.2 * std::cos(theta), 1e-15);
    EXPECT_EQ(gradient[1], 1.0);
    EXPECT_NEAR(time_partial, -0.01, 1e-17);
    EXPECT_NEAR(cam.second_derivative_along(x, rates, t), 9.0 * 0.2 * std::sin(theta), 1e-14);
    EXPECT_EQ(cam.value(x, t), phi);
  }
}

TEST(CoordinateExpression, NonlinearConstraintSecondDerivativesAgainstClosedForm) {
  // Phi = s^2 + r s cos(theta) - L^2 + t theta, r = 0.3, L = 1:
  // Phi_theta = -r s sin + t, Phi_s = 2 s + r cos, Phi_t = theta;
  // Phi_theta,theta = -r s cos, Phi_theta,s = -r sin, Phi_s,s = 2, Phi_theta,t = 1, Phi_s,t = Phi_t,t = 0.
  const double r = 0.3;
  const CoordinateExpression loop("s^2 + r*s*cos(theta) - L^2 + t*theta", {"theta", "s"}, {{"r", r}, {"L", 1.0}});
  for (const double theta : {0.3, 1.9, -2.2}) {
    const double s = 0.8, t = 1.7, vt = -1.3, vs = 0.6;
    const double x[] = {theta, s}, rates[] = {vt, vs};
    double gradient[2], time_partial = 0.0;
    const double phi = loop.gradient(x, t, gradient, time_partial);
    EXPECT_NEAR(phi, s * s + r * s * std::cos(theta) - 1 + t * theta, 1e-14);
    EXPECT_NEAR(gradient[0], -r * s * std::sin(theta) + t, 1e-14);
    EXPECT_NEAR(gradient[1], 2 * s + r * std::cos(theta), 1e-14);
    EXPECT_NEAR(time_partial, theta, 1e-15);
    const double expected = vt * vt * (-r * s * std::cos(theta)) + 2 * vt * vs * (-r * std::sin(theta)) +
                            vs * vs * 2 + 2 * vt * 1.0;
    EXPECT_NEAR(loop.second_derivative_along(x, rates, t), expected, 1e-14);
  }
  EXPECT_TRUE(loop.reads(0));
  EXPECT_TRUE(loop.reads(2));  // t
}

}  // namespace
}  // namespace heavesim
