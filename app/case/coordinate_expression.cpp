#include "app/case/coordinate_expression.hpp"

namespace heavesim {

namespace {
std::vector<std::string> with_time(std::vector<std::string> names) {
  names.push_back("t");
  return names;
}
}  // namespace

CoordinateExpression::CoordinateExpression(const std::string& text, const std::vector<std::string>& coordinates,
                                           const std::map<std::string, double>& parameters)
    : expression_(text, with_time(coordinates), parameters),
      size_(static_cast<int>(coordinates.size())),
      point_(coordinates.size() + 1),
      values_(coordinates.size() + 1) {}

double CoordinateExpression::value(const double* x, double t) const {
  for (int k = 0; k < size_; ++k) values_[k] = x[k];
  values_[size_] = t;
  return expression_.value(values_.data());
}

double CoordinateExpression::gradient(const double* x, double t, double* gradient, double& time_partial) const {
  for (int k = 0; k < size_; ++k) point_[k] = Taylor2(x[k]);
  point_[size_] = Taylor2(t);
  double phi = 0.0;
  // Pass k moves only variable k: the path's first derivative is dPhi/d(variable k).
  for (int k = 0; k <= size_; ++k) {
    point_[k].first = 1.0;
    const Taylor2 result = expression_.evaluate(point_.data());
    point_[k].first = 0.0;
    phi = result.value;
    if (k < size_)
      gradient[k] = result.first;
    else
      time_partial = result.first;
  }
  return phi;
}

double CoordinateExpression::second_derivative_along(const double* x, const double* rates, double t) const {
  for (int k = 0; k < size_; ++k) point_[k] = Taylor2(x[k], rates[k], 0.0);
  point_[size_] = Taylor2::variable(t);
  return expression_.evaluate(point_.data()).second;
}

}  // namespace heavesim
