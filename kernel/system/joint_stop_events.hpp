#pragma once
// One-sided joint stops met by event location, for the integrators that take variable
// steps on the smooth equations (IDA): the event-driven scheme of Pfeiffer & Glocker
// (1996). Between events every stop is either free (its row is not in the equations)
// or active (its row side (q - bound) = 0 holds like any constraint, and its multiplier
// is the stop's force). Events:
//   a free stop's gap side (q - bound) falls through zero   -> an impact
//   an active stop's force (its multiplier) falls through 0 -> it lets go
// At an impact the velocities jump by impulses P that solve, at the fixed configuration,
//   v+ = v- + M^-1 J^T P,   the model's bilateral rows: J v+ = nu(t),
//   each stop at its bound: 0 <= P_s  complementary to  side v+_j + e_s side v-_j >= 0
// (Newton's restitution e_s for approach speeds above the threshold, else e_s = 0): a
// mixed complementarity problem solved by the kernel's fallback chain (Dantzig first).
// A stop that leaves the impact at rest on its bound becomes active when the force that
// keeps it there is compressive (the acceleration-level check, one stop at a time).
// docs/physics/contact.md, "Event-located stops under IDA".
//
// Pfeiffer, F., Glocker, C. (1996). Multibody Dynamics with Unilateral Contacts. Wiley.
#include <vector>

#include "kernel/complementarity/fallback_chain.hpp"
#include "kernel/system/multibody_system.hpp"

namespace heavesim {

struct JointStopEventOptions {
  /// m/s or rad/s: impacts approaching slower than this do not bounce (and so the stop
  /// comes to rest on its bound after finitely many bounces: no Zeno chatter).
  double restitution_threshold = 0.05;
};

class JointStopEvents {
 public:
  /// The model's JointStopConstraint rows (none: count() == 0).
  explicit JointStopEvents(MultibodySystem& system, JointStopEventOptions options = {});

  /// Stop rows, one event function each.
  int count() const { return static_cast<int>(rows_.size()); }
  /// The constraint row of event e.
  int row(int e) const { return rows_[e]; }
  bool active(int e) const { return system_.data().constraint_active[rows_[e]] != 0.0; }
  /// g_e at the configuration q (nq): side (q_j - bound), plus 1e-12 of the bound's scale
  /// (event_gap), for a free stop; for an active
  /// one its multiplier, `multiplier(row)` (>= 0 while it pushes).
  template <typename Multiplier>
  void values(const VectorX& q, const Multiplier& multiplier, Eigen::Ref<VectorX> g) const {
    for (int e = 0; e < count(); ++e) g[e] = active(e) ? multiplier(rows_[e]) : event_gap(e, q);
  }
  /// The start of a run at (t, state = [q; v; z]): stops that touch their bound with no
  /// speed away from it and would be pressed become active (a body resting on a stop).
  void start(double t, VectorX& state);
  /// At a located event: the impacts of the stops in found (found[e] != 0) that close
  /// and of those already at their bound, the velocity jump, stops that let go, and the
  /// new active set; `state` gets the new velocities (and q exactly on the active
  /// bounds). The impulses are recorded by the system's contact element, if any.
  void handle(double t, VectorX& state, const std::vector<int>& found);

  /// The impulse of each stop row at the last impact [N s or N m s, >= 0].
  const VectorX& last_impulses() const { return impulses_; }

 private:
  double gap(int e, const VectorX& q) const;
  double event_gap(int e, const VectorX& q) const;
  /// Resolves the impact of the stops `closed` at (t, state): v jumps in place.
  void impact(double t, VectorX& state, const std::vector<int>& closed);
  /// Makes `candidates` active, then lets go, one at a time, the one pulling hardest,
  /// until every active stop pushes (the multipliers at (t, state)).
  void settle_active_set(double t, const VectorX& state, std::vector<int> candidates);

  MultibodySystem& system_;
  JointStopEventOptions options_;
  std::vector<int> rows_;              // constraint row of each stop
  std::vector<const JointStopConstraint*> stops_;
  VectorX impulses_;                   // per stop row
  ComplementarityWorkspace workspace_;
};

}  // namespace heavesim
