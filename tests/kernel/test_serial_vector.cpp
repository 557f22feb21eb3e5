// The serial vectors the integrators use (kernel/integrators/serial_vector.hpp): their
// weighted RMS norms against SUNDIALS' own serial implementation of the same
// definition, on the vector itself and on its clones; their linear sums, scalings and
// linear combinations bit for bit against SUNDIALS' own serial operations.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

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

// A vector of SUNDIALS' own serial implementation (no operation replaced) holding `values`.
N_Vector sundials_serial_copy(const std::vector<double>& values, SUNContext context) {
  N_Vector vector = N_VNew_Serial(static_cast<sunindextype>(values.size()), context);
  std::memcpy(N_VGetArrayPointer(vector), values.data(), values.size() * sizeof(double));
  return vector;
}

bool same_bits(N_Vector a, N_Vector b) {
  return N_VGetLength(a) == N_VGetLength(b) &&
         std::memcmp(N_VGetArrayPointer(a), N_VGetArrayPointer(b), N_VGetLength(a) * sizeof(double)) == 0;
}

std::vector<double> random_values(std::mt19937_64& random, sunindextype n) {
  std::uniform_real_distribution<double> value(-1e3, 1e3);
  std::vector<double> values(n);
  for (double& v : values) v = value(random);
  return values;
}

// Every coefficient pair SUNDIALS' N_VLinearSum_Serial treats as its own case (a or b =
// +-1, a = b, a = -b, zeros, neither), with z a third vector, x or y.
TEST(SerialVector, LinearSumsAndScalingsAreSundialsSerialBitForBit) {
  sundials::Context context;
  std::mt19937_64 random(11);
  const double coefficients[] = {1.0, -1.0, 0.0, 2.5, -2.5, 0.3, -7.125e-3};
  for (const sunindextype n : {1, 5, 17, 64}) {
    const std::vector<double> x_values = random_values(random, n), y_values = random_values(random, n);
    N_Vector x = sundials::new_serial_vector(n, context);
    N_Vector y = N_VClone(x), z = N_VClone(x);
    for (const double a : coefficients) {
      for (const double b : coefficients) {
        for (const int output : {0, 1, 2}) {  // z, x, y
          std::memcpy(N_VGetArrayPointer(x), x_values.data(), n * sizeof(double));
          std::memcpy(N_VGetArrayPointer(y), y_values.data(), n * sizeof(double));
          N_Vector x_reference = sundials_serial_copy(x_values, context);
          N_Vector y_reference = sundials_serial_copy(y_values, context);
          N_Vector z_reference = N_VClone(x_reference);
          N_Vector result = output == 0 ? z : output == 1 ? x : y;
          N_Vector result_reference = output == 0 ? z_reference : output == 1 ? x_reference : y_reference;
          N_VLinearSum(a, x, b, y, result);
          N_VLinearSum_Serial(a, x_reference, b, y_reference, result_reference);
          EXPECT_TRUE(same_bits(result, result_reference)) << "a = " << a << ", b = " << b << ", output " << output;
          for (N_Vector vector : {x_reference, y_reference, z_reference}) N_VDestroy(vector);
        }
      }
      for (const bool in_place : {false, true}) {
        std::memcpy(N_VGetArrayPointer(x), x_values.data(), n * sizeof(double));
        N_Vector x_reference = sundials_serial_copy(x_values, context), z_reference = N_VClone(x_reference);
        N_VScale(a, x, in_place ? x : z);
        N_VScale_Serial(a, x_reference, in_place ? x_reference : z_reference);
        EXPECT_TRUE(same_bits(in_place ? x : z, in_place ? x_reference : z_reference)) << "c = " << a;
        for (N_Vector vector : {x_reference, z_reference}) N_VDestroy(vector);
      }
    }
    for (N_Vector vector : {x, y, z}) N_VDestroy(vector);
  }
}

// N_VLinearCombination against what SUNDIALS does for a serial vector without fused
// operations, written out with its own serial calls: z = c_0 X_0, then z = c_i X_i + z.
// 1 to 6 vectors (IDA's orders 0-5), unit coefficients among them, z a fresh vector or X_0.
TEST(SerialVector, LinearCombinationsAreSundialsSerialSumsBitForBit) {
  sundials::Context context;
  std::mt19937_64 random(13);
  std::uniform_real_distribution<double> coefficient(-3.0, 3.0);
  for (const sunindextype n : {1, 17, 40}) {
    for (int count = 1; count <= 6; ++count) {
      for (const bool into_first : {false, true}) {
        std::vector<std::vector<double>> values;
        std::vector<double> coefficients;
        std::vector<N_Vector> vectors, references;
        N_Vector first = sundials::new_serial_vector(n, context);
        for (int i = 0; i < count; ++i) {
          values.push_back(random_values(random, n));
          coefficients.push_back(i == 1 ? 1.0 : i == 2 ? -1.0 : coefficient(random));
          vectors.push_back(i == 0 ? first : N_VClone(first));
          std::memcpy(N_VGetArrayPointer(vectors.back()), values.back().data(), n * sizeof(double));
          references.push_back(sundials_serial_copy(values.back(), context));
        }
        N_Vector z = into_first ? vectors[0] : N_VClone(first);
        N_Vector z_reference = into_first ? references[0] : N_VClone(references[0]);
        ASSERT_EQ(N_VLinearCombination(count, coefficients.data(), vectors.data(), z), 0);
        N_VScale_Serial(coefficients[0], references[0], z_reference);
        for (int i = 1; i < count; ++i) N_VLinearSum_Serial(coefficients[i], references[i], 1.0, z_reference, z_reference);
        EXPECT_TRUE(same_bits(z, z_reference)) << "n = " << n << ", " << count << " vectors";
        // And against the sum written out, to a rounding per term.
        for (sunindextype j = 0; j < n; ++j) {
          double sum = 0.0, magnitude = 0.0;
          for (int i = 0; i < count; ++i) {
            sum += coefficients[i] * values[i][j];
            magnitude += std::abs(coefficients[i] * values[i][j]);
          }
          EXPECT_NEAR(N_VGetArrayPointer(z)[j], sum, 4.0 * count * 1.1e-16 * magnitude);
        }
        if (!into_first) N_VDestroy(z), N_VDestroy(z_reference);
        for (N_Vector vector : vectors) N_VDestroy(vector);
        for (N_Vector vector : references) N_VDestroy(vector);
      }
    }
  }
}

}  // namespace
}  // namespace heavesim
