#pragma once
// How large a run's result is, estimated before it runs, and the refusal of a run
// whose result cannot fit (RunLimits, app/case/case_definition.hpp).
#include "app/case/case_definition.hpp"

namespace heavesim {

struct Scene;

struct RunSize {
  double samples = 0.0;  // output samples, t_start and t_end included
  long columns = 0;      // recorded numbers per sample
  double bytes() const { return samples * static_cast<double>(columns) * 8.0; }  // as doubles (HDF5)
};

/// The samples the run records and the columns the recorder (app/output/recorder.cpp)
/// writes for them: /time, bodies (13), joints (nq + 2 nv), reactions (12 per joint),
/// constraint drift, multipliers and wrenches, force-element channels, energies (3).
RunSize estimate_run_size(const CaseDefinition& definition, const Scene& scene);

/// Throws InputError at output.interval (solver.t_end when the interval is the
/// default) if the result would exceed RunLimits::max_output_bytes and large runs are
/// not allowed.
void check_run_size(const CaseDefinition& definition, const Scene& scene);

}  // namespace heavesim
