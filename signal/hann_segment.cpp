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

std::shared_ptr<const HannSegmentTransform::Window> HannSegmentTransform::window_of_length(int segment_length) {
  // Transforms are made on several threads (a sweep's runs); the windows they share are
  // immutable once made. An entry whose last transform has gone is made again.
  static std::mutex mutex;
  static std::map<int, std::weak_ptr<const Window>> windows;
  const std::lock_guard lock(mutex);
  std::weak_ptr<const Window>& entry = windows[segment_length];
  if (std::shared_ptr<const Window> existing = entry.lock()) return existing;
  auto window = std::make_shared<Window>();
  const int L = segment_length;
  window->coefficients.resize(L);
  for (int n = 0; n < L; ++n) {
    window->coefficients[n] = 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * n / L));
    window->power += window->coefficients[n] * window->coefficients[n];
  }
  entry = window;
  return window;
}

HannSegmentTransform::HannSegmentTransform(int segment_length) {
  if (segment_length < 4 || segment_length % 2 != 0)
    throw std::invalid_argument(fmt::format("Welch segment length {}: expected an even number >= 4", segment_length));
  window_ = window_of_length(segment_length);
}

namespace {

// FFTW's planner is not thread-safe; executing a plan on new arrays (fftw_execute_dft_r2c)
// is. Transforms run on several threads (a sweep's runs, the recorder's helper threads), so
// the plans are made under one lock and kept for the life of the process, one per length
// used (the recorder's are powers of two up to 4096): nothing destroys a plan another
// thread may be executing. Each transform fetches its plan under the lock, which orders the
// plan's making before its use for every thread (a race detector sees that; ~25 ns against
// the transform's ~3 us). The mutex and the plans are never destroyed, so a transform
// dropped during the program's exit still finds them. Both are namespace-scope and
// constant-initialized (no function-local static, whose first-use guard a race detector
// cannot follow); std::mutex has nothing to do at destruction in libstdc++.
//
// FFTW_ESTIMATE: the plan is chosen by FFTW's heuristics, without timing trial transforms,
// so it is the same at every run on one machine (the statistics repeat bit for bit) and
// costs ~1.6 ms once per length instead of tens of milliseconds. For powers of two FFTW's
// transform allocates nothing; for an even length with a large prime factor (e.g. 1018,
// `heavesim rao --segment`) FFTW_ESTIMATE picks Bluestein's or a buffered solver, which
// allocate at every transform.
std::mutex planner_mutex;
std::map<int, fftw_plan>* plans_by_length = nullptr;  // made under planner_mutex, never freed

fftw_plan real_plan_of_length(int length) {
  const std::lock_guard lock(planner_mutex);
  if (plans_by_length == nullptr) plans_by_length = new std::map<int, fftw_plan>;
  std::map<int, fftw_plan>& plans = *plans_by_length;
  if (const auto known = plans.find(length); known != plans.end()) return known->second;
  double* input = fftw_alloc_real(static_cast<std::size_t>(length));
  fftw_complex* output = fftw_alloc_complex(static_cast<std::size_t>(length / 2 + 1));
  const bool allocated = input != nullptr && output != nullptr;
  const fftw_plan plan = allocated ? fftw_plan_dft_r2c_1d(length, input, output, FFTW_ESTIMATE) : nullptr;
  fftw_free(input);  // fftw_free(nullptr) does nothing, as free
  fftw_free(output);
  if (!allocated) throw std::bad_alloc();
  if (plan == nullptr) throw std::runtime_error(fmt::format("FFTW: no real transform of length {}", length));
  plans.emplace(length, plan);
  return plan;
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

const std::vector<std::complex<double>>& HannSegmentTransform::transform(const double* samples) {
  const std::vector<double>& window = window_->coefficients;
  const std::size_t L = window.size();
  double mean = 0.0;
  for (std::size_t n = 0; n < L; ++n) mean += samples[n];
  mean /= static_cast<double>(L);
  thread_local AlignedScratch scratch;
  scratch.reserve(L);
  for (std::size_t n = 0; n < L; ++n) scratch.segment[n] = (samples[n] - mean) * window[n];
  const fftw_plan plan = real_plan_of_length(static_cast<int>(L));
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

}  // namespace heavesim::stats
