#pragma once
// What a path names, before anything opens it: only a regular file of bounded size is
// read. A named pipe's open() blocks until a writer comes, /dev/zero never ends, and a
// directory reads as nothing; each is reported by what it is instead (issue #13).
// The case reader (app/case/case_node.cpp) uses the same check for case files.
#include <cstdint>
#include <string>

namespace heavesim::hydro {

/// The largest data file read (BEM coefficients, hull meshes) [bytes]: far beyond any
/// BEM run's output (the MSS semi's WAMIT files are 1 MB), small enough to read in memory.
inline constexpr std::uintmax_t max_data_file_bytes = std::uintmax_t{1} << 30;  // 1 GiB

/// "" when `path` is a regular file of at most `max_bytes`; otherwise what it is instead
/// ("a named pipe (FIFO)", "a directory", "a file of N bytes", ...). Follows symbolic links.
std::string unreadable_file(const std::string& path, std::uintmax_t max_bytes);

/// Throws DataError naming the path when unreadable_file finds a problem; `kind` says
/// what was expected ("WAMIT file", "STL hull mesh").
void require_readable_data_file(const std::string& path, const std::string& kind);

}  // namespace heavesim::hydro
