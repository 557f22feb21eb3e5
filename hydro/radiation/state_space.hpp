#pragma once
// State-space realisation of the radiation memory, one SISO system per coupled mode
// pair (i, j):  z' = A z + B v_j,  F_i -= C z,  so that K_ij(t) ~ C e^{A t} B
// (D = 0 for causality; docs/physics/hydrodynamics.md §5). Identified from the sampled
// kernel by the eigensystem realisation algorithm (Kung 1978; Kristiansen et al. 2005;
// Taghipour et al. 2008): SVD of the Hankel matrix of K(k h), order n kept, then the
// discrete A_d = e^{A h} taken back to continuous time with the matrix logarithm.
#include <complex>
#include <vector>

#include "hydro/radiation/retardation_kernel.hpp"

namespace heavesim::hydro {

inline constexpr int max_state_space_order = 24;
using StateMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, max_state_space_order, max_state_space_order>;
using StateVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, max_state_space_order, 1>;
using StateRowVector = Eigen::Matrix<double, 1, Eigen::Dynamic, 1, 1, max_state_space_order>;

struct ModePairStateSpace {
  int force_mode = 0;     // i (0-based, WAMIT order)
  int velocity_mode = 0;  // j
  StateMatrix A;          // n x n [1/s]; in modal form (to_modal_form) zero off its three central diagonals
  StateVector B;          // n
  StateRowVector C;       // n, units of K
  double r_squared = 0;   // 1 - sum (K - K_fit)^2 / sum (K - mean K)^2 over the kernel samples
  bool stable = false;    // every eigenvalue of A has a negative real part
  bool reflected_poles = false;  // unstable poles of the raw realisation were mirrored
};

/// Takes `system` to real modal coordinates when its eigenvectors allow: with the
/// pseudo-eigendecomposition A V = V D (D block diagonal, a 1 x 1 block per real pole and
/// a 2 x 2 block [[a, b], [-b, a]] per pair a +- i b), the state z = V w gives
/// w' = D w + V^-1 B v, F -= C V w: the same kernel C e^{At} B (a realisation is defined
/// only up to its state basis), and a product D w of 3n multiply-adds instead of n^2
/// (RadiationMemory::state_derivative). Returns false and leaves `system` as it was when
/// V is ill conditioned (cond > 1e6: poles close together, A nearly defective).
bool to_modal_form(ModePairStateSpace& system);

/// The orders a realisation can have: 2 .. max_state_space_order. Throws
/// ParameterError("state_space_order") otherwise.
void check_state_space_order(int order);

/// Realises one kernel entry K_ij (samples every `time_step` [s]) with `order` states,
/// using at most `max_hankel_size` rows and columns (the samples are decimated so the
/// Hankel matrix spans the whole kernel), in real modal form where that is well
/// conditioned (to_modal_form).
/// Throws ParameterError: "state_space_order" out of range, "kernel_step" when the kernel
/// has fewer than 2 order + 1 samples.
ModePairStateSpace realize_kernel_entry(const RetardationKernel& kernel, int i, int j, int order,
                                        int max_hankel_size = 150);

/// All pairs whose kernel is not negligible (max |K_ij| > threshold max_k max |K_kk|).
std::vector<ModePairStateSpace> realize_kernel(const RetardationKernel& kernel, int order, double threshold = 1e-3);

/// C (i w - A)^-1 B = B_ij(w) + i w (A_ij(w) - A_ij(inf)) of the realisation.
std::complex<double> frequency_response(const ModePairStateSpace& system, double angular_frequency);

}  // namespace heavesim::hydro
