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

}  // namespace

N_Vector new_serial_vector(sunindextype length, SUNContext context) {
  N_Vector vector = N_VNew_Serial(length, context);
  if (!vector) throw std::bad_alloc();
  vector->ops->nvwrmsnorm = weighted_rms_norm;
  vector->ops->nvwrmsnormmask = weighted_rms_norm_mask;
  return vector;
}

}  // namespace heavesim::sundials
