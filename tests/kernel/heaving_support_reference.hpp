#pragma once
// A load carried by a support that heaves, z_s(t) = a sin(omega t), which it can leave
// only one way: hanging on a line of length L below it (offset -L), or resting on it
// (offset 0). By hand: carried, z = z_s + offset, until the support falls away faster
// than g; then it flies, until z_s + offset - z turns positive again, when a plastic
// contact (e = 0) gives it the support's speed. Transitions bisected to 1e-13 s. Used
// by the contact step's hoist line and the event-located stop of a load on a heaving
// floor.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "samples/contact_scenes.hpp"

namespace heavesim::testing {

/// The first t in (from, to] where f turns positive (scanned at 1 ms, then bisected to
/// 1e-13 s); `to` if none.
template <typename F>
double first_positive(const F& f, double from, double to) {
  for (double a = from; a < to; a += 1e-3) {
    const double b = std::min(a + 1e-3, to);
    if (f(b) > 0) {
      double lo = a, hi = b;
      while (hi - lo > 1e-13) (f(0.5 * (lo + hi)) > 0 ? hi : lo) = 0.5 * (lo + hi);
      return hi;
    }
  }
  return to;
}

class HeavingSupportReference {
 public:
  static constexpr double g = 9.81;
  HeavingSupportReference(const samples::HeavingTip& support, double offset) : support_(support), offset_(offset) {}
  double z_support(double t) const { return support_.amplitude * std::sin(support_.omega * t); }
  double v_support(double t) const { return support_.amplitude * support_.omega * std::cos(support_.omega * t); }
  double a_support(double t) const {
    return -support_.amplitude * support_.omega * support_.omega * std::sin(support_.omega * t);
  }
  /// The load's height at each time (ascending); fills the contacts and free phases met.
  std::vector<double> load_height(const std::vector<double>& times) {
    std::vector<double> z;
    // The current phase: from t0 with the load at (z0, v0), carried or free, until `end`.
    double t0 = 0.0, z0 = offset_, v0 = v_support(0.0);
    bool carried = true;
    double end = phase_end(t0, z0, v0, carried);
    for (const double t : times) {
      while (t > end) {
        const double z_end = carried ? z_support(end) + offset_ : flight(z0, v0, t0, end);
        const double v_end = carried ? v_support(end) : v0 - g * (end - t0);
        if (carried) {
          carried = false;
          v0 = v_end;
        } else {
          contacts.push_back({end, v_support(end) - v_end});
          v0 = v_support(end);  // plastic: the load takes the support's speed
          carried = a_support(end) + g >= 0.0;
        }
        t0 = end;
        z0 = z_end;
        end = phase_end(t0, z0, v0, carried);
        if (!carried) free_phases.push_back({t0, end});
      }
      z.push_back(carried ? z_support(t) + offset_ : flight(z0, v0, t0, t));
    }
    return z;
  }
  std::vector<std::pair<double, double>> contacts;     ///< (time, jump in the load's speed)
  std::vector<std::pair<double, double>> free_phases;  ///< intervals off the support

 private:
  static double flight(double z0, double v0, double t0, double t) {
    return z0 + v0 * (t - t0) - 0.5 * g * (t - t0) * (t - t0);
  }
  /// Carried: until the support falls away faster than g. Free: until it is reached again.
  double phase_end(double t0, double z0, double v0, bool carried) const {
    if (carried) return first_positive([&](double s) { return -(a_support(s) + g); }, t0, t0 + 10.0);
    return first_positive([&](double s) { return z_support(s) + offset_ - flight(z0, v0, t0, s); }, t0 + 1e-9,
                          t0 + 10.0);
  }
  samples::HeavingTip support_;
  double offset_;
};

}  // namespace heavesim::testing
