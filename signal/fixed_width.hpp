#pragma once
// A run-time width handed to code templated on it: call(std::integral_constant<int, W>{})
// with W = n when n is one of `Widths`, and W = 0 (the code then reads n at run time)
// otherwise. Why: a loop over a width known at compile time unrolls into register moves
// and SIMD pairs; the same loop over a run-time width of 1 to 8 is a loop per row or a
// memmove call (docs/performance.md, "Issue #18, eleventh round"). Used for the statistics'
// column tiles (moment_accumulator.cpp) and the result file's staged rows
// (app/output/result_file.cpp).
#include <cstddef>
#include <type_traits>

namespace heavesim::stats {

template <int... Widths, class Call>
void call_with_fixed_width(std::ptrdiff_t n, Call&& call) {
  const bool fixed = ((n == Widths && (call(std::integral_constant<int, Widths>{}), true)) || ...);
  if (!fixed) call(std::integral_constant<int, 0>{});
}

}  // namespace heavesim::stats
