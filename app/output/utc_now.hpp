#pragma once
// The current time as ISO 8601 UTC text ("2026-11-24T23:50:00Z"): the created_utc
// attribute of result files and sweep indexes.
#include <chrono>
#include <ctime>
#include <string>

namespace heavesim {

inline std::string utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

}  // namespace heavesim
