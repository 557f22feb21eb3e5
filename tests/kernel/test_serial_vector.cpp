// The serial vectors the integrators use (kernel/integrators/serial_vector.hpp): their
// weighted RMS norms against SUNDIALS' own serial implementation of the same
// definition, on the vector itself and on its clones.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "kernel/integrators/serial_vector.hpp"
#include "kernel/integrators/sundials_support.hpp"

namespace heavesim {
namespace {

TEST(SerialVector, WeightedNormsAreSundialsSerialNorms) {
  sundials::Context context;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> value(-1e3, 1e3), weight(0.0, 1e6), id(-1.0, 1.0);
  for (const sunindextype n : {1, 3, 8, 41, 200}) {
    N_Vector x = sundials::new_serial_vector(n, context);
    N_Vector w = N_VClone(x), mask = N_VClone(x);  // clones carry the same operations
    for (sunindextype i = 0; i < n; ++i) {
      N_VGetArrayPointer(x)[i] = value(random);
      N_VGetArrayPointer(w)[i] = weight(random);
      // IDA's id vector holds 1 and 0; the definition counts every id > 0.
      N_VGetArrayPointer(mask)[i] = i % 3 == 0 ? 0.0 : id(random);
    }
    const double reference = N_VWrmsNorm_Serial(x, w), masked_reference = N_VWrmsNormMask_Serial(x, w, mask);
    // Same terms, another order of addition: n roundings of a positive sum.
    const double tolerance = 4.0 * static_cast<double>(n) * 1.1e-16;
    EXPECT_NEAR(N_VWrmsNorm(x, w), reference, tolerance * reference) << "n = " << n;
    EXPECT_NEAR(N_VWrmsNorm(w, x), reference, tolerance * reference) << "n = " << n;  // on a clone
    EXPECT_NEAR(N_VWrmsNormMask(x, w, mask), masked_reference, tolerance * masked_reference) << "n = " << n;
    // Written out: the components with id > 0, over all n.
    double sum = 0.0;
    for (sunindextype i = 0; i < n; ++i)
      if (N_VGetArrayPointer(mask)[i] > 0.0) sum += std::pow(N_VGetArrayPointer(x)[i] * N_VGetArrayPointer(w)[i], 2);
    EXPECT_NEAR(N_VWrmsNormMask(x, w, mask), std::sqrt(sum / static_cast<double>(n)), tolerance * masked_reference);
    for (N_Vector vector : {x, w, mask}) N_VDestroy(vector);
  }
}

}  // namespace
}  // namespace heavesim
