#pragma once
// Tabulated motion: a time series f(t_i) read from a CSV file (a measured platform
// heave record, say), interpolated by a C2 cubic spline whose derivatives are exact for
// the spline (de Boor, A Practical Guide to Splines, rev. ed., Springer 2001, ch. IX
// and XIII).
//
// The spline is Eigen's B-spline (unsupported/Eigen/Splines) of degree 3 in the
// normalised time u = (t - t_0)/(t_n - t_0), with Eigen's knot averaging (de Boor's
// choice: each interior knot the mean of three consecutive data sites). For evenly
// sampled records that is the not-a-knot spline; for any sampling it reproduces cubic
// polynomials exactly and needs no end condition on f'' -- a natural spline would force
// the acceleration to zero at both ends of a record that has none there.
// The interpolation conditions are solved as a sparse system (4 nonzeros per row), so
// that records of 1e5 samples take milliseconds (Eigen's SplineFitting solves them
// densely, O(n^3)).
#include <string>
#include <vector>

#include <unsupported/Eigen/Splines>

#include "kernel/model/constraint.hpp"

namespace heavesim {

class MotionTable {
 public:
  /// The spline through (times[i], values[i]); times strictly increasing, at least
  /// `minimum_rows` of them, all finite (the reader checks; throws std::invalid_argument).
  MotionTable(const std::vector<double>& times, const std::vector<double>& values);

  /// Reads a CSV file: a header line, then one row per sample, "time [s], value" (m or
  /// rad). Throws hydro::DataError at the file's line for what it cannot use.
  static MotionTable read_csv(const std::string& path);

  static constexpr int minimum_rows = 4;  // a cubic needs four samples

  /// f, f', f'' of the spline at t [s]; beyond the table the end cubics continue (the
  /// case reader keeps runs inside it; an integrator may look a step past t_end).
  DriverMotion operator()(double t) const;
  double start_time() const { return start_; }
  double end_time() const { return end_; }

 private:
  double start_ = 0.0, end_ = 0.0;  // s
  Eigen::Spline<double, 1, 3> spline_;
};

}  // namespace heavesim
