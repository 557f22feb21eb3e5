#include "signal/hann_segment.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <stdexcept>

#include <fftw3.h>
#include <fmt/format.h>

namespace heavesim::stats {

struct HannSegmentLength {
  std::vector<double> coefficients;  // w_n, n = 0 .. L-1
  double power = 0.0;                // sum w_n^2
  fftw_plan plan = nullptr;          // made at the first transform of this length
};

namespace {

// Everything shared per length lives in one map under one lock, for the life of the
// process: transforms are made, used and dropped on several threads (a sweep's runs, the
// recorder's helper threads), and FFTW's planner is not thread-safe while executing a plan
// on new arrays (fftw_execute_dft_r2c) is. Nothing is ever destroyed, so no thread can lose
// a plan another is executing, and a transform dropped during the program's exit still
// finds its length. A run uses a few lengths (the recorder's are powers of two up to 4096).
// The mutex and the map's pointer are namespace-scope and constant-initialized: no
// function-local static, whose first-use guard a race detector cannot follow; std::mutex
// has nothing to do at destruction in libstdc++.
std::mutex shared_lengths_mutex;
std::map<int, HannSegmentLength>* shared_lengths = nullptr;  // made under the mutex, never freed

// FFTW_ESTIMATE: the plan is chosen by FFTW's heuristics, without timing trial transforms,
// so it is the same at every run on one machine (the statistics repeat bit for bit) and
// costs ~1.6 ms once per length instead of tens of milliseconds. For powers of two FFTW's
// transform allocates nothing; for an even length with a large prime factor (e.g. 1018,
// `heavesim rao --segment`) FFTW_ESTIMATE picks Bluestein's or a buffered solver, which
// allocate at every transform. Called under shared_lengths_mutex.
fftw_plan make_real_plan(int length) {
  double* input = fftw_alloc_real(static_cast<std::size_t>(length));
  fftw_complex* output = fftw_alloc_complex(static_cast<std::size_t>(length / 2 + 1));
  const bool allocated = input != nullptr && output != nullptr;
  const fftw_plan plan = allocated ? fftw_plan_dft_r2c_1d(length, input, output, FFTW_ESTIMATE) : nullptr;
  fftw_free(input);  // fftw_free(nullptr) does nothing, as free
  fftw_free(output);
  if (!allocated) throw std::bad_alloc();
  if (plan == nullptr) throw std::runtime_error(fmt::format("FFTW: no real transform of length {}", length));
  return plan;
}

// The window of length L, made by the first transform of that length; its plan waits for
// the first transform() (on the thread that computes statistics, not in a recorder's
// constructor).
HannSegmentLength* shared_length(int L) {
  const std::lock_guard lock(shared_lengths_mutex);
  if (shared_lengths == nullptr) shared_lengths = new std::map<int, HannSegmentLength>;
  const auto [entry, made] = shared_lengths->try_emplace(L);
  HannSegmentLength& shared = entry->second;
  if (made) {
    shared.coefficients.resize(L);
    for (int n = 0; n < L; ++n) {
      shared.coefficients[n] = 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * n / L));
      shared.power += shared.coefficients[n] * shared.coefficients[n];
    }
  }
  return &shared;
}

// The plan of `shared`, made on first use. Fetched under the lock by every transform, which
// orders the plan's making before its use on every thread (~25 ns against the ~3 us
// transform).
fftw_plan plan_of(HannSegmentLength& shared) {
  const std::lock_guard lock(shared_lengths_mutex);
  if (shared.plan == nullptr) shared.plan = make_real_plan(static_cast<int>(shared.coefficients.size()));
  return shared.plan;
}

// Scratch of one transform call, kept by each thread: the windowed segment and, when the
// caller's bins are not aligned as FFTW planned them, the bins. fftw_malloc'd, so aligned
// as the plan's arrays were; grown, never shrunk, so a thread allocates once per length.
struct AlignedScratch {
  AlignedScratch() = default;
  AlignedScratch(const AlignedScratch&) = delete;
  AlignedScratch& operator=(const AlignedScratch&) = delete;
  ~AlignedScratch() {
    fftw_free(segment);
    fftw_free(bins);
  }
  void reserve(std::size_t length) {
    if (length <= capacity) return;
    fftw_free(segment);
    fftw_free(bins);
    segment = fftw_alloc_real(length);
    bins = fftw_alloc_complex(length / 2 + 1);
    capacity = segment != nullptr && bins != nullptr ? length : 0;
    if (capacity == 0) throw std::bad_alloc();
  }
  double* segment = nullptr;
  fftw_complex* bins = nullptr;
  std::size_t capacity = 0;
};

}  // namespace

HannSegmentTransform::HannSegmentTransform(int segment_length) {
  if (segment_length < 4 || segment_length % 2 != 0)
    throw std::invalid_argument(fmt::format("Welch segment length {}: expected an even number >= 4", segment_length));
  shared_ = shared_length(segment_length);
}

// The window is immutable once made (under the lock that handed it out).
int HannSegmentTransform::length() const { return static_cast<int>(shared_->coefficients.size()); }

double HannSegmentTransform::window_power() const { return shared_->power; }

namespace {

// The thread's scratch holding the L samples' mean removed and the window applied:
// x_n = (samples_n - mean) w_n, the input of both transforms below.
AlignedScratch& windowed_segment(const std::vector<double>& window, const double* samples) {
  const std::size_t L = window.size();
  double mean = 0.0;
  for (std::size_t n = 0; n < L; ++n) mean += samples[n];
  mean /= static_cast<double>(L);
  thread_local AlignedScratch scratch;
  scratch.reserve(L);
  for (std::size_t n = 0; n < L; ++n) scratch.segment[n] = (samples[n] - mean) * window[n];
  return scratch;
}

}  // namespace

const std::vector<std::complex<double>>& HannSegmentTransform::transform(const double* samples) {
  const std::size_t L = shared_->coefficients.size();
  AlignedScratch& scratch = windowed_segment(shared_->coefficients, samples);
  const fftw_plan plan = plan_of(*shared_);
  transform_.resize(L / 2 + 1);
  // std::complex<double> is laid out as fftw_complex (C++ [complex.numbers]/4). The plan
  // applies to new arrays aligned as the planning ones (fftw_malloc'd): straight into the
  // bins when they are (glibc's malloc aligns them so), through the scratch otherwise.
  auto* bins = reinterpret_cast<fftw_complex*>(transform_.data());
  const bool aligned_as_planned =
      fftw_alignment_of(reinterpret_cast<double*>(bins)) == fftw_alignment_of(reinterpret_cast<double*>(scratch.bins));
  if (aligned_as_planned) {
    fftw_execute_dft_r2c(plan, scratch.segment, bins);
  } else {
    fftw_execute_dft_r2c(plan, scratch.segment, scratch.bins);
    std::copy_n(reinterpret_cast<const std::complex<double>*>(scratch.bins), L / 2 + 1, transform_.begin());
  }
  return transform_;
}

void HannSegmentTransform::add_power(const double* samples, double* power_sums) {
  const std::size_t L = shared_->coefficients.size();
  AlignedScratch& scratch = windowed_segment(shared_->coefficients, samples);
  fftw_execute_dft_r2c(plan_of(*shared_), scratch.segment, scratch.bins);  // the scratch is aligned as planned
  for (std::size_t k = 0; k <= L / 2; ++k)
    power_sums[k] += scratch.bins[k][0] * scratch.bins[k][0] + scratch.bins[k][1] * scratch.bins[k][1];
}

}  // namespace heavesim::stats
