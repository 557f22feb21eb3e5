#include "hydro/data_error.hpp"

#include <fmt/format.h>

namespace heavesim::hydro {

std::string DataError::describe(const std::string& file, int line, const std::string& found,
                                const std::string& expected) {
  return line > 0 ? fmt::format("{}:{}: found {}; expected {}", file, line, found, expected)
                  : fmt::format("{}: found {}; expected {}", file, found, expected);
}

}  // namespace heavesim::hydro
