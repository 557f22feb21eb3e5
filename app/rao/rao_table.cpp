#include "app/rao/rao_table.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include <fmt/format.h>

#include "app/output/csv_cell.hpp"
#include "app/output/output_error.hpp"
#include "app/output/table_file.hpp"
#include "app/version.hpp"

namespace heavesim {
namespace {

constexpr double no_phase = std::numeric_limits<double>::quiet_NaN();  // of a non-finite value

std::vector<double> amplitudes(const std::vector<std::complex<double>>& values) {
  std::vector<double> out;
  for (const std::complex<double>& v : values) out.push_back(std::abs(v));
  return out;
}

/// arg in degrees, (-180, 180].
std::vector<double> phases(const std::vector<std::complex<double>>& values) {
  std::vector<double> out;
  for (const std::complex<double>& v : values) out.push_back(std::isfinite(std::abs(v)) ? std::arg(v) * 180.0 / M_PI : no_phase);
  return out;
}

/// A number of the RAO table: ten significant digits, empty where it is not finite.
std::string csv_ten_digits(double value) { return std::isfinite(value) ? fmt::format("{:.10g}", value) : ""; }

}  // namespace

std::string rao_channel_key(const std::string& name) {
  std::string key = name.starts_with('/') ? name.substr(1) : name;
  for (char& c : key)
    if (c == '/') c = '.';
  return key;
}

void write_rao_table(const std::string& directory, const RaoTable& table) {
  const std::size_t rows = table.angular_frequencies.size();
  std::vector<double> periods;
  for (double w : table.angular_frequencies) periods.push_back(2 * M_PI / w);

  TableFile file((std::filesystem::path(directory) / "rao.h5").string(), "the RAO file");
  file.attribute("/", "heavesim_version", std::string(heavesim_version));
  file.attribute("/", "method", table.method);
  file.attribute("/", "source", table.source);
  file.attribute("/", "wave_elevation_channel", table.wave_elevation_channel);
  file.attribute("/", "platform", table.platform);
  file.attribute("/", "heading_rad", table.heading);
  if (table.method == "regular_sweep") file.attribute("/", "wave_amplitude_m", table.amplitude);
  file.attribute("/", "phase_convention",
                 std::string("x = Re[RAO a e^{i w t}], eta = Re[a e^{i w t}] at the platform's reference point (mean "
                             "position); positive phase: the response leads the wave crest"));
  file.attribute("/", "frequency_domain_reference", table.reference_note.empty() ? std::string("yes") : table.reference_note);
  file.numbers("/period", periods, 1, "s", "wave period 2 pi / w");
  file.numbers("/frequency", table.angular_frequencies, 1, "rad/s", "angular frequency w");
  if (!table.notes.empty()) file.texts("/note", table.notes, "per row: the run it comes from, or why it is empty");
  std::vector<std::string> names;
  for (const RaoColumn& column : table.columns) names.push_back(column.name);
  file.texts("/channel_names", names, "the channels as given, in order; each is the group /channels/<name with / as .>");
  for (const RaoColumn& column : table.columns) {
    const std::string group = "/channels/" + rao_channel_key(column.name);
    file.numbers(group + "/amplitude", amplitudes(column.values), 1, column.unit, "|RAO| per unit wave amplitude");
    file.numbers(group + "/phase", phases(column.values), 1, "deg", "arg RAO, relative to the wave elevation at the reference point");
    if (!column.coherence.empty())
      file.numbers(group + "/coherence", column.coherence, 1, "-", "ordinary coherence gamma^2 of the H1 estimate");
    if (!column.reference.empty()) {
      file.numbers(group + "/bem_amplitude", amplitudes(column.reference), 1, column.unit, "frequency-domain |RAO| (BEM data)");
      file.numbers(group + "/bem_phase", phases(column.reference), 1, "deg", "frequency-domain arg RAO (BEM data)");
    }
    if (!column.reference_on_bem.empty()) {
      file.numbers(group + "/bem_line_amplitude", amplitudes(column.reference_on_bem), 1, column.unit,
                   "frequency-domain |RAO| at /bem_frequency");
      file.numbers(group + "/bem_line_phase", phases(column.reference_on_bem), 1, "deg",
                   "frequency-domain arg RAO at /bem_frequency");
    }
    file.attribute(group, "name", column.name);
  }
  if (!table.bem_frequencies.empty())
    file.numbers("/bem_frequency", table.bem_frequencies, 1, "rad/s", "frequencies of the frequency-domain RAO line: the BEM frequencies and 7 between each pair");
  file.close();

  const std::string csv_path = (std::filesystem::path(directory) / "rao.csv").string();
  std::ofstream csv(csv_path);
  if (!csv) throw OutputError(csv_path, "cannot create the RAO table", std::strerror(errno));
  csv << "period [s],frequency [rad/s]";
  for (const RaoColumn& c : table.columns) {
    csv << "," << csv_text(c.name + " amplitude [" + c.unit + "]") << "," << csv_text(c.name + " phase [deg]");
    if (!c.coherence.empty()) csv << "," << csv_text(c.name + " coherence [-]");
    if (!c.reference.empty())
      csv << "," << csv_text(c.name + " bem amplitude [" + c.unit + "]") << "," << csv_text(c.name + " bem phase [deg]");
  }
  csv << "\n";
  for (std::size_t r = 0; r < rows; ++r) {
    csv << csv_ten_digits(periods[r]) << "," << csv_ten_digits(table.angular_frequencies[r]);
    for (const RaoColumn& c : table.columns) {
      csv << "," << csv_ten_digits(std::abs(c.values[r])) << "," << csv_ten_digits(phases({c.values[r]})[0]);
      if (!c.coherence.empty()) csv << "," << csv_ten_digits(c.coherence[r]);
      if (!c.reference.empty())
        csv << "," << csv_ten_digits(std::abs(c.reference[r])) << "," << csv_ten_digits(phases({c.reference[r]})[0]);
    }
    csv << "\n";
  }
  if (!csv.flush()) throw OutputError(csv_path, "cannot write the RAO table", std::strerror(errno));
}

}  // namespace heavesim
