#pragma once
// SUNDIALS serial N_Vectors whose hot operations are Eigen expressions.
//
// Why: Debian 12's SUNDIALS 6.4.1 libraries are built without optimization (objdump of
// libsundials_ida.so.6: every loop counter and local lives on the stack, -O0 code), so
// each serial vector operation costs about 25 instructions per component and term: a
// 6-term linear combination of 17 components takes ~2,600 instructions against ~150
// for the same sums compiled here (2026-11-30). IDA and ARKODE spend most of their own
// time in these operations: the weighted RMS norms (the error test at orders k-1, k,
// k+1, Newton's convergence test), the linear sums and scalings of the predictor and
// corrector, and the linear combinations of the predictor and of IDAGetSolution's
// interpolation at every output time (N_VLinearSum and N_VScale, most of them reached
// through N_VLinearCombination, were 13.6 % of the drilling run's instructions, about
// half of its integration's, before this). SUNDIALS lets a vector carry its own
// operations; the integrators' internal vectors are clones of the state vector and
// inherit them.
//
// The norms are the same sums
//   ||x||_w = sqrt( (1/n) sum_i (x_i w_i)^2 ),  masked: over the i with id_i > 0
// (SUNDIALS' definition, nvector_serial.c), added in another order (vectorized). The
// linear sums, scalings and linear combinations make SUNDIALS' own roundings in SUNDIALS'
// own order, so integrating gives the same bits as before
// (tests/kernel/test_serial_vector.cpp against the library's serial operations). That
// needs products and sums rounded one at a time: kernel/CMakeLists.txt compiles this file
// with -ffp-contract=off, so that a target with FMA (aarch64, -march=native) does not fuse
// them.
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

namespace heavesim::sundials {

/// A new serial vector of `length` components with the Eigen operations (nvwrmsnorm,
/// nvwrmsnormmask, nvlinearsum, nvscale, nvlinearcombination); N_VDestroy frees it.
N_Vector new_serial_vector(sunindextype length, SUNContext context);

}  // namespace heavesim::sundials
