#pragma once
// glibc's vector math library, libmvec: libm's functions on two doubles at once (the x86-64
// vector function ABI, SSE variant 'b'; glibc picks the implementation for the processor at
// load time). Their errors are within 4 ulp of the correctly rounded result (glibc manual,
// "Errors in Math Functions"). Eigen 3.4 vectorizes cos for float only: on doubles its
// .cos() is a loop of scalar libm calls, 3-4 times slower for the wave elevation's sum
// (measured with the large arguments of a 3-hour sea, w t up to 3e4 rad).
//
// HEAVESIM_HAVE_LIBMVEC is set by the build target heavesim_vector_libm (kernel/CMakeLists.txt)
// when libmvec is found on x86-64; without it the callers run their scalar loops. (Its log1p
// was tried for the Pareto fit's likelihood and was no faster than libm's.)
#include <cmath>
#include <cstddef>
#include <vector>

#if defined(HEAVESIM_HAVE_LIBMVEC)
#include <emmintrin.h>

extern "C" {
__m128d _ZGVbN2v_cos(__m128d);  // cos, two lanes
__m128d _ZGVbN2v_sin(__m128d);  // sin, two lanes
}

namespace heavesim::vector_libm {
inline __m128d cos(__m128d x) { return _ZGVbN2v_cos(x); }
inline __m128d sin(__m128d x) { return _ZGVbN2v_sin(x); }
/// The sum of the two lanes.
inline double lane_sum(__m128d x) {
  alignas(16) double lanes[2];
  _mm_store_pd(lanes, x);
  return lanes[0] + lanes[1];
}
}  // namespace heavesim::vector_libm
#endif

namespace heavesim::vector_libm {
/// cosines[j] = cos(w[j] t) and sines[j] = sin(w[j] t) for j < n: two at a time through
/// libmvec where it is linked, libm's scalar functions otherwise (and for an odd last one).
inline void cos_sin_of_scaled(const double* w, double t, double* cosines, double* sines, std::ptrdiff_t n) {
  std::ptrdiff_t j = 0;
#if defined(HEAVESIM_HAVE_LIBMVEC)
  const __m128d scale = _mm_set1_pd(t);
  for (; j + 2 <= n; j += 2) {
    const __m128d x = _mm_mul_pd(_mm_loadu_pd(w + j), scale);
    _mm_storeu_pd(cosines + j, cos(x));
    _mm_storeu_pd(sines + j, sin(x));
  }
#endif
  for (; j < n; ++j) {
    cosines[j] = std::cos(w[j] * t);
    sines[j] = std::sin(w[j] * t);
  }
}

/// cosines[i] = cos(x[i]) and sines[i] = sin(x[i]) for the indices i listed: two at a time
/// through libmvec where it is linked (two cos and two sin in 10.5 ns against 18.3 ns for
/// two scalar sincos, small arguments, this machine 2026-11-29), an odd last one by libm.
inline void cos_sin_at(const double* x, const std::vector<int>& indices, double* cosines, double* sines) {
  const std::size_t n = indices.size();
  std::size_t k = 0;
#if defined(HEAVESIM_HAVE_LIBMVEC)
  for (; k + 2 <= n; k += 2) {
    const int a = indices[k], b = indices[k + 1];
    const __m128d angles = _mm_set_pd(x[b], x[a]);
    alignas(16) double c[2], s[2];
    _mm_store_pd(c, cos(angles));
    _mm_store_pd(s, sin(angles));
    cosines[a] = c[0], cosines[b] = c[1];
    sines[a] = s[0], sines[b] = s[1];
  }
#endif
  for (; k < n; ++k) {
    cosines[indices[k]] = std::cos(x[indices[k]]);
    sines[indices[k]] = std::sin(x[indices[k]]);
  }
}
}  // namespace heavesim::vector_libm
