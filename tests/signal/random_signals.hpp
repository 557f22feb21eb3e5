#pragma once
// Reproducible random numbers for the statistics tests: std::mt19937_64 is specified
// bit for bit by the standard, the distributions are not, so uniforms and normals are
// made here from its raw output (53-bit uniforms; Box-Muller normals).
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace heavesim::testing {

class RandomSource {
 public:
  explicit RandomSource(std::uint64_t seed) : engine_(seed) {}
  /// Uniform on (0, 1): never 0 or 1, so that logarithms of it are finite.
  double uniform() { return (static_cast<double>(engine_() >> 11) + 0.5) * 0x1.0p-53; }
  double normal() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double radius = std::sqrt(-2.0 * std::log(uniform()));
    const double angle = 2.0 * std::numbers::pi * uniform();
    spare_ = radius * std::sin(angle);
    has_spare_ = true;
    return radius * std::cos(angle);
  }

 private:
  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace heavesim::testing
