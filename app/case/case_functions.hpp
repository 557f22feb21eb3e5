#pragma once
// The functions of case expressions (docs/case-format.md, "Numbers and expressions"),
// written once for any scalar: double when muParser evaluates a number, Taylor2
// (taylor_scalar.hpp) when an expression is differentiated. muParser's own built-ins
// are replaced by these (define_case_functions, expression.hpp) so that every function
// an expression can call has a known derivative rule, and values and derivatives come
// from the same code.
#include <cmath>
#include <numbers>

#include "app/case/taylor_scalar.hpp"

namespace heavesim {

enum class CaseFunction {
  sin, cos, tan, asin, acos, atan, atan2, sinh, cosh, tanh, asinh, acosh, atanh,
  log2, log10, ln, exp, sqrt, sign, rint, abs, deg, rad,
  sum, avg, min, max,       // any number of arguments
  step, step5, ramp, smoothstep,  // the motion helpers
};

struct CaseFunctionEntry {
  const char* name;
  CaseFunction function;
  int arguments;  // -1: any number (at least one)
};

/// Every function of case expressions, muParser's names (log and ln are both ln).
inline constexpr CaseFunctionEntry case_function_table[] = {
    {"sin", CaseFunction::sin, 1},        {"cos", CaseFunction::cos, 1},
    {"tan", CaseFunction::tan, 1},        {"asin", CaseFunction::asin, 1},
    {"acos", CaseFunction::acos, 1},      {"atan", CaseFunction::atan, 1},
    {"atan2", CaseFunction::atan2, 2},    {"sinh", CaseFunction::sinh, 1},
    {"cosh", CaseFunction::cosh, 1},      {"tanh", CaseFunction::tanh, 1},
    {"asinh", CaseFunction::asinh, 1},    {"acosh", CaseFunction::acosh, 1},
    {"atanh", CaseFunction::atanh, 1},    {"log2", CaseFunction::log2, 1},
    {"log10", CaseFunction::log10, 1},    {"log", CaseFunction::ln, 1},
    {"ln", CaseFunction::ln, 1},          {"exp", CaseFunction::exp, 1},
    {"sqrt", CaseFunction::sqrt, 1},      {"sign", CaseFunction::sign, 1},
    {"rint", CaseFunction::rint, 1},      {"abs", CaseFunction::abs, 1},
    {"deg", CaseFunction::deg, 1},        {"rad", CaseFunction::rad, 1},
    {"sum", CaseFunction::sum, -1},       {"avg", CaseFunction::avg, -1},
    {"min", CaseFunction::min, -1},       {"max", CaseFunction::max, -1},
    {"step", CaseFunction::step, 5},      {"step5", CaseFunction::step5, 5},
    {"ramp", CaseFunction::ramp, 3},      {"smoothstep", CaseFunction::smoothstep, 3},
};

/// ADAMS' STEP(x, x0, h0, x1, h1): h0 up to x0, h1 from x1, between them the cubic
/// h0 + (h1 - h0) d^2 (3 - 2 d), d = (x - x0)/(x1 - x0): C1 (zero slope at both ends).
/// `quintic`: STEP5's h0 + (h1 - h0) d^3 (10 - 15 d + 6 d^2), C2 (zero slope and
/// curvature at both ends). Not a number unless x0 < x1.
template <class Scalar>
Scalar step_function(const Scalar& x, const Scalar& x0, const Scalar& h0, const Scalar& x1, const Scalar& h1,
                     bool quintic) {
  if (!(value_of(x0) < value_of(x1))) return Scalar(std::nan(""));
  if (value_of(x) <= value_of(x0)) return h0;
  if (value_of(x) >= value_of(x1)) return h1;
  const Scalar d = (x - x0) / (x1 - x0);
  const Scalar shape = quintic ? d * d * d * (Scalar(10.0) - Scalar(15.0) * d + Scalar(6.0) * d * d)
                               : d * d * (Scalar(3.0) - Scalar(2.0) * d);
  return h0 + (h1 - h0) * shape;
}

/// f(args[0], ..., args[count - 1]) for any scalar with the arithmetic and functions of
/// taylor_scalar.hpp. Non-smooth functions (abs, sign, rint, min, max, the helpers at
/// their ends) take the derivative of the branch active at the point.
template <class Scalar>
Scalar apply_case_function(CaseFunction function, const Scalar* args, int count) {
  using std::abs, std::acos, std::acosh, std::asin, std::asinh, std::atan, std::atan2, std::atanh, std::cos,
      std::cosh, std::exp, std::log, std::log10, std::log2, std::sin, std::sinh, std::sqrt, std::tan, std::tanh;
  const Scalar& x = args[0];
  switch (function) {
    case CaseFunction::sin: return sin(x);
    case CaseFunction::cos: return cos(x);
    case CaseFunction::tan: return tan(x);
    case CaseFunction::asin: return asin(x);
    case CaseFunction::acos: return acos(x);
    case CaseFunction::atan: return atan(x);
    case CaseFunction::atan2: return atan2(x, args[1]);
    case CaseFunction::sinh: return sinh(x);
    case CaseFunction::cosh: return cosh(x);
    case CaseFunction::tanh: return tanh(x);
    case CaseFunction::asinh: return asinh(x);
    case CaseFunction::acosh: return acosh(x);
    case CaseFunction::atanh: return atanh(x);
    case CaseFunction::log2: return log2(x);
    case CaseFunction::log10: return log10(x);
    case CaseFunction::ln: return log(x);
    case CaseFunction::exp: return exp(x);
    case CaseFunction::sqrt: return sqrt(x);
    case CaseFunction::sign: return Scalar(sign(value_of(x)));
    case CaseFunction::rint: return Scalar(std::floor(value_of(x) + 0.5));  // muParser's: half up
    case CaseFunction::abs: return value_of(x) < 0.0 ? -x : x;
    case CaseFunction::deg: return x * Scalar(std::numbers::pi / 180.0);  // degrees to radians
    case CaseFunction::rad: return x * Scalar(180.0 / std::numbers::pi);  // radians to degrees
    case CaseFunction::sum:
    case CaseFunction::avg: {
      Scalar total = x;
      for (int k = 1; k < count; ++k) total = total + args[k];
      return function == CaseFunction::sum ? total : total / Scalar(static_cast<double>(count));
    }
    case CaseFunction::min:
    case CaseFunction::max: {
      int active = 0;  // the first argument of the least (greatest) value
      for (int k = 1; k < count; ++k)
        if (function == CaseFunction::min ? value_of(args[k]) < value_of(args[active])
                                          : value_of(args[k]) > value_of(args[active]))
          active = k;
      return args[active];
    }
    case CaseFunction::step: return step_function(x, args[1], args[2], args[3], args[4], false);
    case CaseFunction::step5: return step_function(x, args[1], args[2], args[3], args[4], true);
    case CaseFunction::ramp: {  // 0 up to x0, 1 from x1, linear between
      if (!(value_of(args[1]) < value_of(args[2]))) return Scalar(std::nan(""));
      if (value_of(x) <= value_of(args[1])) return Scalar(0.0);
      if (value_of(x) >= value_of(args[2])) return Scalar(1.0);
      return (x - args[1]) / (args[2] - args[1]);
    }
    case CaseFunction::smoothstep: return step_function(x, args[1], Scalar(0.0), args[2], Scalar(1.0), true);
  }
  return Scalar(std::nan(""));
}

/// The callbacks muParser calls, by number of arguments; their user data is the
/// CaseFunctionEntry. The differentiating evaluator (taylor_evaluation.hpp) recognises
/// a function token by these addresses and reads the entry.
double call_case_function_1(void* entry, double a);
double call_case_function_2(void* entry, double a, double b);
double call_case_function_3(void* entry, double a, double b, double c);
double call_case_function_5(void* entry, double a, double b, double c, double d, double e);
double call_case_function_n(void* entry, const double* args, int count);
/// Unary minus and plus (muParser's infix operators carry no user data).
double case_unary_minus(double x);
double case_unary_plus(double x);

}  // namespace heavesim
