#include "kernel/integrators/serial_vector.hpp"

#include <cmath>
#include <new>

#include "kernel/integrators/sundials_support.hpp"

namespace heavesim::sundials {
namespace {

realtype weighted_rms_norm(N_Vector x, N_Vector w) {
  const Eigen::Map<VectorX> values = map(x), weights = map(w);
  return std::sqrt((values.array() * weights.array()).square().sum() / static_cast<double>(values.size()));
}

realtype weighted_rms_norm_mask(N_Vector x, N_Vector w, N_Vector id) {
  const Eigen::Map<VectorX> values = map(x), weights = map(w), mask = map(id);
  const auto counted = (mask.array() > 0.0).select(values.array() * weights.array(), 0.0);
  return std::sqrt(counted.square().sum() / static_cast<double>(values.size()));
}

// z = a x + b y with the roundings of SUNDIALS' N_VLinearSum_Serial, which picks a
// special case by the coefficients. Four branches give its results bit for bit, signed
// zeros included (tests/kernel/test_serial_vector.cpp):
//   a = -1:   b y - x      (its VLin2 and VDiff, and y -= x in place: -(x - y) would make
//                           -0 where x = y, and -(x + y) where x = -y)
//   a = b:    a (x + y)    (VScaleSum; VSum when a = 1)
//   a = -b:   a (x - y)    (VScaleDiff; VDiff when a = 1)
//   else:     a x + b y    (its VLin1, VLin2 with b = -1, y += a x and the general case:
//                           1 x = x, t + (-y) = t - y and addition commutes, in IEEE too)
// z may be x or y: every component reads its own x_i, y_i before it writes z_i.
void linear_sum(realtype a, N_Vector x, realtype b, N_Vector y, N_Vector z) {
  const Eigen::Map<VectorX> first = map(x), second = map(y);
  Eigen::Map<VectorX> result = map(z);
  if (a == -1.0)
    result = b * second - first;
  else if (a == b)
    result = a * (first + second);
  else if (a == -b)
    result = a * (first - second);
  else
    result = a * first + b * second;
}

// z = c x (N_VScale_Serial: a copy for c = 1 and a negation for c = -1, the same bits).
void scale(realtype c, N_Vector x, N_Vector z) { map(z) = c * map(x); }

// z = sum_i c_i X_i, added left to right as SUNDIALS' generic N_VLinearCombination does
// when the vector has no fused operation (z = c_0 X_0, then z = c_i X_i + z for i >= 1):
// the same roundings in one call instead of nvec. z may be any X_i.
int linear_combination(int count, realtype* coefficients, N_Vector* vectors, N_Vector z) {
  Eigen::Map<VectorX> result = map(z);
  result = coefficients[0] * map(vectors[0]);
  for (int i = 1; i < count; ++i) result = coefficients[i] * map(vectors[i]) + result;
  return 0;
}

}  // namespace

N_Vector new_serial_vector(sunindextype length, SUNContext context) {
  N_Vector vector = N_VNew_Serial(length, context);
  if (!vector) throw std::bad_alloc();
  vector->ops->nvwrmsnorm = weighted_rms_norm;
  vector->ops->nvwrmsnormmask = weighted_rms_norm_mask;
  vector->ops->nvlinearsum = linear_sum;
  vector->ops->nvscale = scale;
  vector->ops->nvlinearcombination = linear_combination;
  return vector;
}

}  // namespace heavesim::sundials
