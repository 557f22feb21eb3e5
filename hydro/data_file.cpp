#include "hydro/data_file.hpp"

#include <filesystem>
#include <system_error>

#include "hydro/data_error.hpp"

namespace heavesim::hydro {

std::string unreadable_file(const std::string& path, std::uintmax_t max_bytes) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);  // follows symbolic links
  switch (status.type()) {
    case fs::file_type::not_found:
      return "a path that does not exist";
    case fs::file_type::directory:
      return "a directory";
    case fs::file_type::fifo:
      return "a named pipe (FIFO)";
    case fs::file_type::character:
      return "a character device";
    case fs::file_type::block:
      return "a block device";
    case fs::file_type::socket:
      return "a socket";
    case fs::file_type::regular: {
      const std::uintmax_t size = fs::file_size(path, error);
      if (error) break;
      if (size > max_bytes) return "a file of " + std::to_string(size) + " bytes";
      return "";
    }
    default:
      break;
  }
  if (error) return "a path that cannot be examined (" + error.message() + ")";
  return "something other than a regular file";
}

void require_readable_data_file(const std::string& path, const std::string& kind) {
  if (const std::string problem = unreadable_file(path, max_data_file_bytes); !problem.empty())
    throw DataError(path, 0, problem,
                    "a readable " + kind + " (a regular file of at most " + std::to_string(max_data_file_bytes) +
                        " bytes)");
}

}  // namespace heavesim::hydro
