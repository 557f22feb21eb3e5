#pragma once
// SUNDIALS serial N_Vectors whose weighted RMS norms are Eigen expressions.
//
// Why: IDA and ARKODE take several weighted RMS norms of the state a step (the error
// test at orders k-1, k, k+1, Newton's convergence test), and SUNDIALS 6.4's serial
// norms are scalar loops behind two indirect calls: 179 ns for 40 components against
// 21 ns for the same sum as an Eigen expression on this machine (2026-11-29), 6.9 % of
// the 3-hour H1 run. The norms are the same sums
//   ||x||_w = sqrt( (1/n) sum_i (x_i w_i)^2 ),  masked: over the i with id_i > 0
// (SUNDIALS' definition, nvector_serial.c), added in another order (vectorized).
// SUNDIALS lets a vector carry its own operations; the integrators' internal vectors
// are clones of the state vector and inherit them.
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

namespace heavesim::sundials {

/// A new serial vector of `length` components with the Eigen norms (nvwrmsnorm,
/// nvwrmsnormmask); N_VDestroy frees it.
N_Vector new_serial_vector(sunindextype length, SUNContext context);

}  // namespace heavesim::sundials
