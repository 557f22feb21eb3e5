#pragma once
// The turning points of a sampled signal (its local maxima and minima, with its first and
// last samples), kept as the signal streams by, and the zero-up-crossing cycles about any
// level found from them afterwards.
//
// Why turning points: the statistics are taken about the mean of the whole window, which
// is known only at its end, and the recorder must not read the series a second time.
// Between two successive turning points the signal is monotone, so it up-crosses a level m
// (a sample x_i < m <= x_(i+1), the definition used here) exactly once in that stretch if
// and only if the stretch starts below m and ends at or above it; and the largest value
// between two up-crossings is one of the turning points. Crossing counts, crests and troughs
// about the final mean are therefore exact, from at most one stored value per sample (two
// per cycle for a smooth response: about 1/100 of the samples at 50 samples a cycle).
#include <cstdint>
#include <vector>

namespace heavesim::stats {

class TurningPoints {
 public:
  void add(double x);
  /// The turning points so far, alternating minima and maxima, the last sample included.
  /// Valid until the next add().
  const std::vector<double>& values();
  std::int64_t samples() const { return samples_; }

 private:
  std::vector<double> points_;
  double last_ = 0.0;
  int trend_ = 0;  // +1 rising, -1 falling, 0 not yet known (flat so far)
  std::int64_t samples_ = 0;
  bool last_pushed_ = false;  // whether points_ ends with the provisional last sample
};

/// The zero-up-crossing cycles of a signal about `level`: complete cycles only (from one
/// up-crossing to the next); the stretches before the first and after the last up-crossing
/// are left out.
struct Cycles {
  std::int64_t upcrossings = 0;
  std::vector<double> crests;   // per complete cycle, its largest value (absolute, units of the signal)
  std::vector<double> troughs;  // per complete cycle, its smallest value
};
Cycles zero_upcrossing_cycles(const std::vector<double>& turning_points, double level);

}  // namespace heavesim::stats
