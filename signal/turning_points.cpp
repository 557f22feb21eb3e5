#include "signal/turning_points.hpp"

#include <algorithm>

namespace heavesim::stats {

void TurningPoints::add(double x) {
  if (last_pushed_) {
    points_.pop_back();  // the previous last sample was provisional
    last_pushed_ = false;
  }
  if (samples_ == 0) {
    points_.push_back(x);  // the first sample starts the first monotone stretch
  } else if (x > last_) {
    if (trend_ < 0) points_.push_back(last_);  // last_ was a local minimum
    trend_ = 1;
  } else if (x < last_) {
    if (trend_ > 0) points_.push_back(last_);  // last_ was a local maximum
    trend_ = -1;
  }
  last_ = x;
  ++samples_;
}

const std::vector<double>& TurningPoints::values() {
  if (samples_ > 1 && !last_pushed_) {
    points_.push_back(last_);
    last_pushed_ = true;
  }
  return points_;
}

Cycles zero_upcrossing_cycles(const std::vector<double>& points, double level) {
  Cycles cycles;
  bool in_cycle = false;
  double crest = 0.0, trough = 0.0;
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    const double from = points[k], to = points[k + 1];
    if (from < level && to >= level) {
      ++cycles.upcrossings;
      if (in_cycle) {
        // The stretch (from, to] is monotone: the cycle ended inside it, below `to`; its
        // smallest value so far includes `from`.
        cycles.crests.push_back(crest);
        cycles.troughs.push_back(std::min(trough, from));
      }
      in_cycle = true;
      crest = to;
      trough = to;
      continue;
    }
    if (in_cycle) {
      crest = std::max(crest, to);
      trough = std::min(trough, to);
    }
  }
  return cycles;
}

}  // namespace heavesim::stats
