#pragma once
// HEAVESIM_CLONED_FOR_AVX2 before a function definition: GCC compiles the function twice,
// for the x86-64 baseline the project builds for and for x86-64-v3 (AVX2, FMA), and the
// loader picks the version the processor runs (GCC's function multiversioning,
// target_clones, through an ifunc). For plain loops the compiler vectorizes: 4 doubles a
// vector instead of 2, and fused multiply-adds (rounded once instead of twice, so results
// differ from the baseline's in the last bits). Elsewhere (other compilers, the checked
// clang build, other processors, C libraries without ifunc) the attribute is empty and
// the baseline version runs. (x86-64-v3 as a target name: GCC 11 and later.)
#include <cstdlib>  // defines __GLIBC__ on glibc

#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 11 && defined(__x86_64__) && defined(__GLIBC__)
#define HEAVESIM_CLONED_FOR_AVX2 __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define HEAVESIM_CLONED_FOR_AVX2
#endif
