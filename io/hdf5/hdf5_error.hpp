#pragma once
// The cause of the last HDF5 failure, in words a user can act on. HDF5 records every
// failure on its error stack (HDF5 Reference Manual, H5E); the innermost entry is the
// one that knows what went wrong. A failed write in the sec2 (POSIX) driver reads
// "file write failed: ..., errno = 28, error message = 'No space left on device', ...":
// that system error is the cause to report; elsewhere the innermost description is.
#include <hdf5.h>

#include <string>

namespace heavesim::hdf5 {

namespace detail {
struct ErrorWalk {
  std::string innermost, system_error;
};
inline herr_t record_error(unsigned depth, const H5E_error2_t* error, void* data) {
  auto* walk = static_cast<ErrorWalk*>(data);
  const std::string description = error->desc ? error->desc : "";
  if (depth == 0) walk->innermost = description;
  const std::string marker = "error message = '";
  const std::size_t start = description.find(marker);
  if (walk->system_error.empty() && start != std::string::npos) {
    const std::size_t end = description.find('\'', start + marker.size());
    walk->system_error = description.substr(start + marker.size(), end - start - marker.size());
    const std::size_t errno_at = description.find("errno = ");
    if (errno_at != std::string::npos)
      walk->system_error += " (errno " + description.substr(errno_at + 8, description.find(',', errno_at) - errno_at - 8) + ")";
  }
  return 0;
}
}  // namespace detail

/// Turns off HDF5's printing of every failure's error stack on the calling thread: the
/// callers report failures from the return codes (last_error). In Debian's thread-safe
/// HDF5 the setting is per thread, so each thread that calls HDF5 makes it.
inline void report_errors_by_return_codes() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

/// The system error of the last failed HDF5 call if it had one ("No space left on
/// device (errno 28)"), else HDF5's own innermost message; `fallback` if the stack is empty.
/// Clears the stack.
inline std::string last_error(const std::string& fallback = "unknown HDF5 error") {
  detail::ErrorWalk walk;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, detail::record_error, &walk);
  H5Eclear2(H5E_DEFAULT);
  if (!walk.system_error.empty()) return walk.system_error;
  return walk.innermost.empty() ? fallback : walk.innermost;
}

}  // namespace heavesim::hdf5
