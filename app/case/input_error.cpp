#include "app/case/input_error.hpp"

namespace heavesim {

std::string SourceLocation::to_string() const {
  if (line <= 0) return file;
  return file + ":" + std::to_string(line) + ":" + std::to_string(column);
}

namespace {
std::string compose(const SourceLocation& location, const std::string& key_path, const std::string& found,
                    const std::string& expected) {
  std::string message = location.to_string() + ": ";
  if (!key_path.empty()) message += key_path + ": ";
  message += "found " + found + "; expected " + expected;
  return message;
}
}  // namespace

InputError::InputError(SourceLocation location, std::string key_path, std::string found, std::string expected)
    : std::runtime_error(compose(location, key_path, found, expected)),
      location_(std::move(location)),
      key_path_(std::move(key_path)),
      found_(std::move(found)),
      expected_(std::move(expected)) {}

}  // namespace heavesim
