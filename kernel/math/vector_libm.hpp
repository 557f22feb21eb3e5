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
#if defined(HEAVESIM_HAVE_LIBMVEC)
#include <emmintrin.h>

extern "C" {
__m128d _ZGVbN2v_cos(__m128d);  // cos, two lanes
}

namespace heavesim::vector_libm {
inline __m128d cos(__m128d x) { return _ZGVbN2v_cos(x); }
/// The sum of the two lanes.
inline double lane_sum(__m128d x) {
  alignas(16) double lanes[2];
  _mm_store_pd(lanes, x);
  return lanes[0] + lanes[1];
}
}  // namespace heavesim::vector_libm
#endif
