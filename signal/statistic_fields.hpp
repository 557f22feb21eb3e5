#pragma once
// The names, units and meanings of the response statistics as they are written and
// printed: one table for the result file's dataset attributes (app/output/recorder.cpp),
// `heavesim stats` (text and JSON) and any reader, so that a name means one thing
// everywhere. docs/result-file.md lists the same names (checked by a test).
#include <string>
#include <vector>

#include "signal/response_statistics.hpp"

namespace heavesim::stats {

/// How a statistic's unit follows from the channel's unit u.
enum class FieldUnit { signal, none, seconds, count, signal_squared, signal_squared_hz2, signal_squared_hz4 };

/// What a statistic needs: the moments only, the cycles (turning points), or the spectrum.
enum class FieldGroup { moments, cycles, spectrum };

struct StatisticField {
  const char* name;         // attribute / JSON key
  FieldGroup group;
  FieldUnit unit;
  const char* description;  // one line, for the table and the docs
  double (*value)(const ResponseStatistics&);
};

/// Every scalar statistic of a column, in the order printed.
const std::vector<StatisticField>& statistic_fields();

/// The unit text of `unit` for a channel whose unit is `channel_units` ("N" -> "N^2/Hz" ...).
std::string unit_text(FieldUnit unit, const std::string& channel_units);

}  // namespace heavesim::stats
