#pragma once
// Stroke end stops: a one-sided penalty spring-damper beyond [lower, upper]
// (docs/physics/compensators.md §5: k = 1e8 N/m, c = 1e6 N s/m beyond +-3.81 m). The contact
// force is max(0, k delta + c d(delta)/dt) for penetration delta > 0: the damper
// resists entry and exit but never pulls the stroke back into the stop.
//
// EndStopMonitor counts contacts (bottoming at the lower stop, topping out at the
// upper one) from a sequence of sampled strokes: a contact that begins and ends
// between two samples is missed, so sample faster than half a contact's duration
// (pi / sqrt(k / m): 0.17 s for 290 t on 1e8 N/m).
#include <limits>

namespace heavesim {

struct EndStops {
  double lower = -std::numeric_limits<double>::infinity();  // m, stroke of the lower stop
  double upper = std::numeric_limits<double>::infinity();   // m, stroke of the upper stop (> lower)
  double stiffness = 1e8;                                   // N/m
  double damping = 1e6;                                     // N s/m
};

/// Force [N] of the stops on the moving side at stroke s [m] and rate v [m/s]:
/// positive (extending) at the lower stop, negative at the upper one, 0 between.
inline double end_stop_force(const EndStops& stops, double stroke, double rate) {
  if (stroke < stops.lower) {
    const double push = stops.stiffness * (stops.lower - stroke) - stops.damping * rate;
    return push > 0.0 ? push : 0.0;
  }
  if (stroke > stops.upper) {
    const double push = stops.stiffness * (stroke - stops.upper) + stops.damping * rate;
    return push > 0.0 ? -push : 0.0;
  }
  return 0.0;
}

/// Energy [J] stored in the stops' springs at stroke s [m]: k delta^2 / 2 for the
/// penetration delta beyond a stop (the dampers store nothing).
inline double end_stop_energy(const EndStops& stops, double stroke) {
  const double delta = stroke < stops.lower ? stops.lower - stroke : stroke > stops.upper ? stroke - stops.upper : 0.0;
  return 0.5 * stops.stiffness * delta * delta;
}

/// Which stop a stroke is in: -1 lower, +1 upper, 0 none.
inline int end_stop_contact(const EndStops& stops, double stroke) {
  return stroke < stops.lower ? -1 : stroke > stops.upper ? 1 : 0;
}

class EndStopMonitor {
 public:
  explicit EndStopMonitor(const EndStops& stops) : stops_(stops) {}
  /// Takes the next sampled stroke [m].
  void observe(double stroke) {
    const int contact = end_stop_contact(stops_, stroke);
    if (contact != 0 && contact != previous_) ++(contact < 0 ? lower_events_ : upper_events_);
    if (contact < 0 && stops_.lower - stroke > max_penetration_) max_penetration_ = stops_.lower - stroke;
    if (contact > 0 && stroke - stops_.upper > max_penetration_) max_penetration_ = stroke - stops_.upper;
    previous_ = contact;
  }
  long lower_events() const { return lower_events_; }  // bottoming events
  long upper_events() const { return upper_events_; }  // topping-out events
  double max_penetration() const { return max_penetration_; }  // m

 private:
  EndStops stops_;
  int previous_ = 0;
  long lower_events_ = 0, upper_events_ = 0;
  double max_penetration_ = 0.0;
};

}  // namespace heavesim
