// The serial vectors the integrators use (kernel/integrators/serial_vector.hpp): their
// weighted RMS norms against SUNDIALS' own serial implementation of the same
// definition, on the vector itself and on its clones; their linear sums, scalings and
// linear combinations bit for bit against SUNDIALS' own serial operations.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>
#include <random>
#include <tuple>
#include <utility>
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

// Every component the same bits, signed zeros told apart; any NaN equals any NaN (SUNDIALS
// negates by flipping the sign bit, -1 x keeps a NaN's: no computation reads it).
bool same_bits(N_Vector a, N_Vector b) {
  if (N_VGetLength(a) != N_VGetLength(b)) return false;
  for (sunindextype i = 0; i < N_VGetLength(a); ++i) {
    const double u = N_VGetArrayPointer(a)[i], v = N_VGetArrayPointer(b)[i];
    if (std::isnan(u) && std::isnan(v)) continue;
    if (std::memcmp(&u, &v, sizeof(double)) != 0) return false;
  }
  return true;
}

std::vector<double> random_values(std::mt19937_64& random, sunindextype n) {
  std::uniform_real_distribution<double> value(-1e3, 1e3);
  std::vector<double> values(n);
  for (double& v : values) v = value(random);
  return values;
}

// Where the special cases could part: x_i = y_i and x_i = -y_i (exact cancellation, the sign
// of the zero it makes), signed zeros, an infinity; as many as n holds, in that order.
void add_special_components(std::vector<double>& x, std::vector<double>& y) {
  const double infinity = std::numeric_limits<double>::infinity();
  const std::pair<double, double> pairs[] = {{x[0], x[0]},   {x.size() > 1 ? x[1] : 0.0, -(x.size() > 1 ? x[1] : 0.0)},
                                             {0.0, -0.0},    {-0.0, 0.0},
                                             {-0.0, -0.0},   {infinity, 2.0},
                                             {3.0, -infinity}};
  for (std::size_t i = 0; i < std::min(x.size(), std::size(pairs)); ++i) std::tie(x[i], y[i]) = pairs[i];
}

// Every coefficient pair SUNDIALS' N_VLinearSum_Serial treats as its own case (a or b =
// +-1, a = b, a = -b, zeros, neither), with z a third vector, x or y, on components that
// cancel exactly, signed zeros and infinities as well as random ones.
TEST(SerialVector, LinearSumsAndScalingsAreSundialsSerialBitForBit) {
  sundials::Context context;
  std::mt19937_64 random(11);
  const double coefficients[] = {1.0, -1.0, 0.0, -0.0, 2.5, -2.5, 0.3, -7.125e-3};
  for (const sunindextype n : {1, 5, 17, 64}) {
    std::vector<double> x_values = random_values(random, n), y_values = random_values(random, n);
    add_special_components(x_values, y_values);
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
// 1 to 6 vectors (IDA's orders 0-5), unit coefficients among them (c_0 too), components
// that cancel exactly and signed zeros; z a fresh vector, X_0, or the last X_i (which the
// first step overwrites, in SUNDIALS' order as in ours).
TEST(SerialVector, LinearCombinationsAreSundialsSerialSumsBitForBit) {
  sundials::Context context;
  std::mt19937_64 random(13);
  std::uniform_real_distribution<double> coefficient(-3.0, 3.0);
  enum class Output { fresh, first, last };
  for (const sunindextype n : {1, 17, 40}) {
    for (int count = 1; count <= 6; ++count) {
      for (const Output output : {Output::fresh, Output::first, Output::last}) {
        if (output == Output::last && count < 2) continue;
        std::vector<std::vector<double>> values;
        std::vector<double> coefficients;
        std::vector<N_Vector> vectors, references;
        const double c0 = count % 3 == 0 ? 1.0 : count % 3 == 1 ? -1.0 : coefficient(random);
        for (int i = 0; i < count; ++i) {
          values.push_back(random_values(random, n));
          coefficients.push_back(i == 0 ? c0 : i == 1 ? 1.0 : i == 2 ? -1.0 : coefficient(random));
        }
        if (count >= 2) add_special_components(values[0], values[1]);
        N_Vector first = sundials::new_serial_vector(n, context);
        for (int i = 0; i < count; ++i) {
          vectors.push_back(i == 0 ? first : N_VClone(first));
          std::memcpy(N_VGetArrayPointer(vectors.back()), values[i].data(), n * sizeof(double));
          references.push_back(sundials_serial_copy(values[i], context));
        }
        const bool owns_z = output == Output::fresh;
        N_Vector z = output == Output::fresh   ? N_VClone(first)
                     : output == Output::first ? vectors[0]
                                               : vectors[count - 1];
        N_Vector z_reference = output == Output::fresh   ? N_VClone(references[0])
                               : output == Output::first ? references[0]
                                                         : references[count - 1];
        ASSERT_EQ(N_VLinearCombination(count, coefficients.data(), vectors.data(), z), 0);
        N_VScale_Serial(coefficients[0], references[0], z_reference);
        for (int i = 1; i < count; ++i) N_VLinearSum_Serial(coefficients[i], references[i], 1.0, z_reference, z_reference);
        EXPECT_TRUE(same_bits(z, z_reference)) << "n = " << n << ", " << count << " vectors, output "
                                               << static_cast<int>(output);
        // And against the sum written out, to a rounding per term (not when z was a term
        // after the first, which the first step overwrote).
        for (sunindextype j = 0; output != Output::last && j < n; ++j) {
          double sum = 0.0, magnitude = 0.0;
          for (int i = 0; i < count; ++i) {
            sum += coefficients[i] * values[i][j];
            magnitude += std::abs(coefficients[i] * values[i][j]);
          }
          const double value = N_VGetArrayPointer(z)[j];
          if (std::isfinite(sum))
            EXPECT_NEAR(value, sum, 4.0 * count * 1.1e-16 * magnitude);
          else  // an infinite term: the same infinity, or NaN where two cancel
            EXPECT_TRUE(value == sum || (std::isnan(value) && std::isnan(sum))) << value << " against " << sum;
        }
        if (owns_z) {
          N_VDestroy(z);
          N_VDestroy(z_reference);
        }
        for (N_Vector vector : vectors) N_VDestroy(vector);
        for (N_Vector vector : references) N_VDestroy(vector);
      }
    }
  }
}

}  // namespace
}  // namespace heavesim
