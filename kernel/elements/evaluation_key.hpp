#pragma once
// What a force element's evaluation is a function of, kept with what it computed so
// that the same evaluation asked again is read back instead of recomputed. One
// evaluation of a system asks an element several times at the same point: apply() and
// state_derivative() in every residual, then outputs(), potential_energy() and the
// run's summary at every recorded sample (docs/performance.md, "Issue #18, tenth round").
//
// The key is the stages' evaluation number (StageMarker::evaluation, unique in the
// process, renewed by every position or velocity stage), the time t [s] and the
// element's internal states z. An element whose loads are a function of (t, q, v, z)
// alone (ElementDependencies::history false) gives the same answer for the same key, so
// it may skip the computation; one with history (a radiation convolution) may still read
// back what its last apply() gave at that key, never compute less.
// Mutable state inside a const element: one element is evaluated by one thread at a
// time (ForceElement's contract: a scene per thread, as the recorder's second thread
// has its own build).
#include <limits>

#include "kernel/model/data.hpp"

namespace heavesim {

class EvaluationKey {
 public:
  /// Whether (data's evaluation, t, z) is the point stored last. Never before store().
  bool matches(const Data& data, double t, Eigen::Ref<const VectorX> z) const {
    return same_stages(data) && t == time_ && z.size() == states_.size() && z == states_;
  }
  /// Whether data holds the stages stored last, whatever t and z: for what depends on
  /// the stages alone (a body's pose).
  bool same_stages(const Data& data) const { return evaluation_ != 0 && data.stages.evaluation == evaluation_; }
  /// Keeps (data's evaluation, t, z). Allocates only when z's size changes (the first call).
  void store(const Data& data, double t, Eigen::Ref<const VectorX> z) {
    evaluation_ = data.stages.evaluation;
    time_ = t;
    states_ = z;
  }
  /// Forget the point (the next matches() is false).
  void clear() { evaluation_ = 0; }
  /// Runs `compute` (what the element keeps at this point) and keeps the point: nothing
  /// is kept if it throws.
  template <class Compute>
  void keep(const Data& data, double t, Eigen::Ref<const VectorX> z, Compute&& compute) {
    clear();
    compute();
    store(data, t, z);
  }

 private:
  long evaluation_ = 0;  // 0: nothing stored (no stage has number 0)
  double time_ = std::numeric_limits<double>::quiet_NaN();
  VectorX states_;
};

}  // namespace heavesim
