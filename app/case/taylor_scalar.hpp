#pragma once
// A second-order Taylor scalar: a quantity x(s) along a path s, held as its value and
// its first two derivatives at s = 0 (Griewank & Walther, Evaluating Derivatives, 2nd
// ed., SIAM 2008, ch. 13: univariate Taylor propagation, truncated at degree 2).
//
// Arithmetic on these scalars propagates the derivatives exactly (to round-off): an
// expression evaluated with t(s) = t + s gives f(t), f'(t), f''(t); with the
// coordinates q(s) = q + s v and t(s) = t + s it gives the directional second
// derivative v' Phi_qq v + 2 Phi_qt . v + Phi_tt of a constraint in one pass.
//
// Every elementary function g enters through one rule, the chain rule to second order:
//   (g o x)'  = g'(x) x',   (g o x)'' = g'(x) x'' + g''(x) x'^2,
// so each needs only g, g' and g'' at the point (taylor_functions below).
#include <cmath>

namespace heavesim {

struct Taylor2 {
  double value = 0.0;   // x(0)
  double first = 0.0;   // x'(0)
  double second = 0.0;  // x''(0)

  Taylor2() = default;
  explicit Taylor2(double constant) : value(constant) {}  // a constant: no derivatives
  Taylor2(double v, double d1, double d2) : value(v), first(d1), second(d2) {}

  /// The path variable itself plus an offset: x(s) = x0 + s (t with t(s) = t + s).
  static Taylor2 variable(double x0, double rate = 1.0) { return {x0, rate, 0.0}; }
};

inline double value_of(double x) { return x; }
inline double value_of(const Taylor2& x) { return x.value; }

/// g(x(s)) from g, g', g'' at x(0).
inline Taylor2 chain(const Taylor2& x, double g, double g1, double g2) {
  // Skip the terms of a constant argument: g' may be infinite where x' is 0 (sqrt(0)).
  if (x.first == 0.0 && x.second == 0.0) return {g, 0.0, 0.0};
  return {g, g1 * x.first, g1 * x.second + g2 * x.first * x.first};
}

/// g(a(s), b(s)) from g and its partial derivatives to second order at (a(0), b(0)).
inline Taylor2 chain(const Taylor2& a, const Taylor2& b, double g, double ga, double gb, double gaa, double gab,
                     double gbb) {
  return {g, ga * a.first + gb * b.first,
          ga * a.second + gb * b.second + gaa * a.first * a.first + 2.0 * gab * a.first * b.first +
              gbb * b.first * b.first};
}

inline Taylor2 operator-(const Taylor2& x) { return {-x.value, -x.first, -x.second}; }
inline Taylor2 operator+(const Taylor2& a, const Taylor2& b) {
  return {a.value + b.value, a.first + b.first, a.second + b.second};
}
inline Taylor2 operator-(const Taylor2& a, const Taylor2& b) {
  return {a.value - b.value, a.first - b.first, a.second - b.second};
}
/// Leibniz: (ab)'' = a'' b + 2 a' b' + a b''.
inline Taylor2 operator*(const Taylor2& a, const Taylor2& b) {
  return {a.value * b.value, a.first * b.value + a.value * b.first,
          a.second * b.value + 2.0 * a.first * b.first + a.value * b.second};
}
/// q = a / b from q b = a: q' = (a' - q b') / b, q'' = (a'' - 2 q' b' - q b'') / b.
inline Taylor2 operator/(const Taylor2& a, const Taylor2& b) {
  const double q = a.value / b.value;
  const double q1 = (a.first - q * b.first) / b.value;
  return {q, q1, (a.second - 2.0 * q1 * b.first - q * b.second) / b.value};
}
inline Taylor2& operator+=(Taylor2& a, const Taylor2& b) { return a = a + b; }

// The elementary functions of case expressions (docs/case-format.md, "Numbers and
// expressions"), each by its g, g', g''.
inline Taylor2 sin(const Taylor2& x) {
  const double s = std::sin(x.value), c = std::cos(x.value);
  return chain(x, s, c, -s);
}
inline Taylor2 cos(const Taylor2& x) {
  const double s = std::sin(x.value), c = std::cos(x.value);
  return chain(x, c, -s, -c);
}
inline Taylor2 tan(const Taylor2& x) {  // tan' = 1 + tan^2, tan'' = 2 tan (1 + tan^2)
  const double t = std::tan(x.value), d = 1.0 + t * t;
  return chain(x, t, d, 2.0 * t * d);
}
inline Taylor2 asin(const Taylor2& x) {  // 1/sqrt(1 - x^2), x/(1 - x^2)^(3/2)
  const double r = 1.0 - x.value * x.value, d = 1.0 / std::sqrt(r);
  return chain(x, std::asin(x.value), d, x.value * d / r);
}
inline Taylor2 acos(const Taylor2& x) {
  const double r = 1.0 - x.value * x.value, d = 1.0 / std::sqrt(r);
  return chain(x, std::acos(x.value), -d, -x.value * d / r);
}
inline Taylor2 atan(const Taylor2& x) {  // 1/(1 + x^2), -2x/(1 + x^2)^2
  const double d = 1.0 / (1.0 + x.value * x.value);
  return chain(x, std::atan(x.value), d, -2.0 * x.value * d * d);
}
/// atan2(y, x): g_y = x/r2, g_x = -y/r2, g_yy = -2xy/r2^2, g_yx = (y^2 - x^2)/r2^2, g_xx = 2xy/r2^2.
inline Taylor2 atan2(const Taylor2& y, const Taylor2& x) {
  const double r2 = x.value * x.value + y.value * y.value, r4 = r2 * r2;
  return chain(y, x, std::atan2(y.value, x.value), x.value / r2, -y.value / r2, -2.0 * x.value * y.value / r4,
               (y.value * y.value - x.value * x.value) / r4, 2.0 * x.value * y.value / r4);
}
inline Taylor2 sinh(const Taylor2& x) {
  const double s = std::sinh(x.value), c = std::cosh(x.value);
  return chain(x, s, c, s);
}
inline Taylor2 cosh(const Taylor2& x) {
  const double s = std::sinh(x.value), c = std::cosh(x.value);
  return chain(x, c, s, c);
}
inline Taylor2 tanh(const Taylor2& x) {  // 1 - tanh^2, -2 tanh (1 - tanh^2)
  const double t = std::tanh(x.value), d = 1.0 - t * t;
  return chain(x, t, d, -2.0 * t * d);
}
inline Taylor2 asinh(const Taylor2& x) {  // 1/sqrt(x^2 + 1), -x/(x^2 + 1)^(3/2)
  const double r = x.value * x.value + 1.0, d = 1.0 / std::sqrt(r);
  return chain(x, std::asinh(x.value), d, -x.value * d / r);
}
inline Taylor2 acosh(const Taylor2& x) {  // 1/sqrt(x^2 - 1), -x/(x^2 - 1)^(3/2)
  const double r = x.value * x.value - 1.0, d = 1.0 / std::sqrt(r);
  return chain(x, std::acosh(x.value), d, -x.value * d / r);
}
inline Taylor2 atanh(const Taylor2& x) {  // 1/(1 - x^2), 2x/(1 - x^2)^2
  const double d = 1.0 / (1.0 - x.value * x.value);
  return chain(x, std::atanh(x.value), d, 2.0 * x.value * d * d);
}
inline Taylor2 exp(const Taylor2& x) {
  const double e = std::exp(x.value);
  return chain(x, e, e, e);
}
inline Taylor2 log(const Taylor2& x) {  // 1/x, -1/x^2
  const double d = 1.0 / x.value;
  return chain(x, std::log(x.value), d, -d * d);
}
inline Taylor2 log10(const Taylor2& x) {
  const double d = 1.0 / (x.value * std::log(10.0));
  return chain(x, std::log10(x.value), d, -d / x.value);
}
inline Taylor2 log2(const Taylor2& x) {
  const double d = 1.0 / (x.value * std::log(2.0));
  return chain(x, std::log2(x.value), d, -d / x.value);
}
inline Taylor2 sqrt(const Taylor2& x) {  // 1/(2 sqrt x), -1/(4 x sqrt x)
  const double r = std::sqrt(x.value);
  return chain(x, r, 0.5 / r, -0.25 / (r * x.value));
}
/// The sign of x: -1, 0 or 1 (muParser's).
inline double sign(double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); }
/// x^y: a constant exponent by the power rule (exact at x = 0 for integer y); otherwise
/// exp(y ln x), defined for x > 0.
inline Taylor2 pow(const Taylor2& x, const Taylor2& y) {
  const double p = std::pow(x.value, y.value);
  if (y.first == 0.0 && y.second == 0.0) {
    const double c = y.value;
    if (c == 0.0) return {p, 0.0, 0.0};
    const double g1 = c * std::pow(x.value, c - 1.0);
    const double g2 = c == 1.0 ? 0.0 : c * (c - 1.0) * std::pow(x.value, c - 2.0);
    return chain(x, p, g1, g2);
  }
  const double l = std::log(x.value);  // g = x^y: g_x = y x^(y-1), g_y = x^y ln x
  return chain(x, y, p, y.value * p / x.value, p * l, y.value * (y.value - 1.0) * p / (x.value * x.value),
               p * (1.0 + y.value * l) / x.value, p * l * l);
}

}  // namespace heavesim
