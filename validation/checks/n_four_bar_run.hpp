#pragma once
// One run of an IFToMM A02 N-four-bar case (cases/validation/iftomm_a02_n*.yaml, written
// by scripts/make_iftomm_a02.py) against the exact parallelogram motion
// (oracles/four_bar_parallelogram), for any N: validation L2 (N = 1, 2, 10 s) and A02
// (N = 10, 40, 20 s, the benchmark's size).
#include <string>

namespace heavesim::validation {

struct NFourBarErrors {
  bool completed = false;     // the run reached t_end
  double time_reached = 0.0;  // s, the last time the integrator reached
  // Both infinite when the run did not complete (a failed run is an infinite error).
  double tip_error = 0.0;     // m, max |B0 - (-sin q, cos q)| over the 0.01 s samples
  double branch_error = 0.0;  // rad, max |q_crank - q_crank0| and |coupler angle|
};

NFourBarErrors run_n_four_bar(const std::string& case_path, int windows);

}  // namespace heavesim::validation
