// heavesim rao (docs/rao.md): response amplitude operators per unit wave amplitude,
//  * from a case: a regular-wave period sweep. Each run is the case with its `waves:`
//    replaced (the --set mechanism) by regular waves of one period and the given
//    amplitude, heading and ramp kept; the runs go through app/sweep's task distribution
//    (-j N worker processes), each as `heavesim run --quiet` would; every channel and
//    the recorded incident elevation are fitted by least squares over the last whole
//    wave cycles after output.evaluate_after (signal/harmonic_fit.hpp), RAO = X / X_eta;
//  * from a result file of an irregular sea: the H1 estimator G_xy / G_xx with its
//    coherence (signal/cross_spectrum.hpp), input the recorded incident elevation, over
//    the run's evaluation window.
// Both use the elevation at the platform's reference point that the case's
// wave_excitation element records, so the phase is relative to that point's crest. Where
// the case has BEM data, the frequency-domain RAO (app/rao/frequency_domain_reference.hpp)
// is written beside them. Output: DIR/rao.h5, DIR/rao.csv and the figure DIR/rao.png
// drawn by scripts/plot_rao.py (Debian's /usr/bin/python3 with matplotlib, as
// `heavesim operability` runs its script).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "app/case/case_definition.hpp"
#include "app/output/output_error.hpp"
#include "app/rao/frequency_domain_reference.hpp"
#include "app/rao/rao_channel.hpp"
#include "app/rao/rao_table.hpp"
#include "app/sweep/run_record.hpp"
#include "app/sweep/task_distribution.hpp"
#include "app/version.hpp"
#include "cli/commands/command_support.hpp"
#include "cli/commands/commands.hpp"
#include "cli/commands/logged_run.hpp"
#include "cli/commands/project_script.hpp"
#include "cli/commands/recorded_time.hpp"
#include "io/hdf5/hdf5_reader.hpp"
#include "signal/cross_spectrum.hpp"
#include "signal/harmonic_fit.hpp"

namespace heavesim {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr int largest_period_count = 1000;

InputError argument_error(const std::string& argument, const std::string& found, const std::string& expected) {
  return InputError(SourceLocation{argument, 0, 0}, "", found, expected);
}

/// --periods "A:STEP:B" (A, A + STEP, ... up to B) or "T1,T2,..." [s], each in 0.1 .. 1000 s.
std::vector<double> parse_periods(const std::string& text) {
  const std::string expected = "periods in s as A:STEP:B (A, A+STEP, ... <= B; 0 < A <= B, STEP > 0) or T1,T2,... "
                               "(each 0.1 .. 1000 s, at most 1000 periods)";
  const auto number = [&](const std::string& word) {
    std::size_t used = 0;
    double value = nan;
    try {
      value = std::stod(word, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || word.find_first_not_of(" ", used) != std::string::npos || !std::isfinite(value))
      throw argument_error("--periods", "'" + text + "'", expected);
    return value;
  };
  std::vector<double> periods;
  if (text.find(':') != std::string::npos) {
    const std::size_t first = text.find(':'), second = text.find(':', first + 1);
    if (second == std::string::npos || text.find(':', second + 1) != std::string::npos)
      throw argument_error("--periods", "'" + text + "'", expected);
    const double from = number(text.substr(0, first)), step = number(text.substr(first + 1, second - first - 1)),
                 to = number(text.substr(second + 1));
    if (!(step > 0) || !(to >= from) || (to - from) / step > largest_period_count)
      throw argument_error("--periods", "'" + text + "'", expected);
    for (long k = 0; from + static_cast<double>(k) * step <= to + 1e-9 * step; ++k)
      periods.push_back(from + static_cast<double>(k) * step);
  } else {
    std::size_t start = 0;
    while (start <= text.size()) {
      const std::size_t comma = std::min(text.find(',', start), text.size());
      const std::string word = text.substr(start, comma - start);
      if (word.find_first_not_of(' ') != std::string::npos) periods.push_back(number(word));
      start = comma + 1;
    }
  }
  if (periods.empty()) throw argument_error("--periods", "an empty list ('" + text + "')", expected);
  if (periods.size() > largest_period_count)
    throw argument_error("--periods", fmt::format("{} periods", periods.size()), expected);
  for (double period : periods)
    if (!(period >= 0.1 && period <= 1000.0)) throw argument_error("--periods", fmt::format("a period of {} s", period), expected);
  return periods;
}

/// The regular sea of one run: `waves:` replaced whole (the ramp kept as the case has it).
std::string regular_waves_override(const WaveDefinition& waves, double amplitude, double period) {
  std::string ramp = "none";
  if (waves.ramp.kind == hydro::RampKind::cosine) ramp = fmt::format("{{kind: cosine, duration: {:.17g}}}", waves.ramp.duration);
  if (waves.ramp.kind == hydro::RampKind::hyperbolic_tangent)
    ramp = fmt::format("{{kind: tanh, duration: {:.17g}}}", waves.ramp.duration);
  return fmt::format("waves={{type: regular, amplitude: {:.17g}, period: {:.17g}, heading: {:.17g}, ramp: {}}}", amplitude,
                     period, waves.heading, ramp == "none" ? "{kind: none}" : ramp);
}

/// output.channels with the groups the RAO needs (bodies for modes and points, forces for
/// the elevation, and the group of every requested series), so that a case recording less
/// still gives them and one recording more does not pay for reactions it does not need.
/// Nothing when a channel lies outside those groups (the case's own choice then stands).
std::optional<std::string> output_channels_override(const std::vector<RaoChannel>& channels) {
  bool bodies = false, joints = false, reactions = false, energy = false;
  for (const RaoChannel& channel : channels) {
    if (channel.mode >= 0 || channel.point || channel.dataset.starts_with("/bodies/")) {
      bodies = true;
    } else if (channel.dataset.starts_with("/joints/")) {
      (channel.dataset.find("/reaction_") != std::string::npos ? reactions : joints) = true;
    } else if (channel.dataset.starts_with("/signals/") && channel.dataset.find("energy") != std::string::npos) {
      energy = true;
    } else if (!channel.dataset.starts_with("/forces/")) {
      return std::nullopt;
    }
  }
  std::string list = "forces";
  if (bodies) list += ", bodies";
  if (joints) list += ", joints";
  if (reactions) list += ", reactions";
  if (energy) list += ", energy";
  return "output.channels=[" + list + "]";
}

RaoColumn empty_column(const std::string& name) { return RaoColumn{name, "", {}, {}, {}, {}}; }

std::string per_wave_unit(const std::string& unit) { return unit + "/m"; }

/// A mode's reference in the table's units (rotations in deg/m).
std::complex<double> reference_in_units(const hydro::ComplexVector6& xi, int mode) {
  return mode >= 3 ? xi[mode] * (180.0 / M_PI) : xi[mode];
}

/// Adds the frequency-domain RAO to the mode columns, per row and on the BEM frequencies.
void add_reference(RaoTable& table, const std::vector<RaoChannel>& channels, const CaseDefinition& definition) {
  const std::optional<FrequencyDomainReference> reference =
      FrequencyDomainReference::of_case(definition, table.reference_note);
  if (!reference) return;
  // The line: the BEM frequencies and 7 between each pair, so that it follows what the
  // interpolated coefficients give between them (the points' own reference) rather than
  // drawing chords across the wide gaps of a BEM grid.
  const std::vector<double>& bem = reference->bem_frequencies();
  for (std::size_t n = 0; n < bem.size(); ++n)
    for (int k = 0; k < (n + 1 < bem.size() ? 8 : 1); ++k) table.bem_frequencies.push_back(bem[n] + (n + 1 < bem.size() ? k * (bem[n + 1] - bem[n]) / 8 : 0.0));
  std::vector<hydro::ComplexVector6> rows, line;
  for (double w : table.angular_frequencies) rows.push_back(reference->rao(w));
  for (double w : table.bem_frequencies) line.push_back(reference->rao(w));
  for (std::size_t c = 0; c < channels.size(); ++c) {
    const int mode = channels[c].mode;
    if (mode < 0) continue;
    for (const hydro::ComplexVector6& xi : rows) table.columns[c].reference.push_back(reference_in_units(xi, mode));
    for (const hydro::ComplexVector6& xi : line) table.columns[c].reference_on_bem.push_back(reference_in_units(xi, mode));
  }
}

/// Per mode column with a reference: rows compared (coherence > 0.9 for H1, the RAO at
/// least 10 % of its largest over them) and the worst amplitude ratio error and phase error.
void print_comparison(const RaoTable& table) {
  for (const RaoColumn& column : table.columns) {
    if (column.reference.empty()) continue;
    double largest = 0.0;
    for (std::size_t r = 0; r < column.reference.size(); ++r)
      if (column.coherence.empty() || column.coherence[r] > 0.9) largest = std::max(largest, std::abs(column.reference[r]));
    int compared = 0;
    double worst_amplitude = 0.0, worst_phase = 0.0;
    for (std::size_t r = 0; r < column.reference.size(); ++r) {
      if (!column.coherence.empty() && !(column.coherence[r] > 0.9)) continue;
      if (std::abs(column.reference[r]) < 0.1 * largest || !std::isfinite(std::abs(column.values[r]))) continue;
      ++compared;
      worst_amplitude = std::max(worst_amplitude, std::abs(std::abs(column.values[r]) / std::abs(column.reference[r]) - 1.0));
      worst_phase = std::max(worst_phase, std::abs(std::arg(column.values[r] / column.reference[r])) * 180.0 / M_PI);
    }
    fmt::print("  {:<8} against the frequency-domain RAO at {} {}: worst amplitude {:.2f} %, phase {:.2f} deg\n", column.name,
               compared, table.method == "h1" ? "bins (coherence > 0.9, |RAO| >= 10 % of its largest)" : "periods (|RAO| >= 10 % of its largest)",
               100 * worst_amplitude, worst_phase);
  }
}

/// Runs scripts/plot_rao.py on DIR/rao.h5 (a child process; its exit code).
int draw_figure(const std::string& directory) {
  return run_project_script("plot_rao.py", {(std::filesystem::path(directory) / "rao.h5").string()});
}

std::string output_directory(const RaoOptions& options) {
  const std::string directory = options.output_directory.empty()
                                    ? "results/" + std::filesystem::path(options.input).stem().string() + "_rao"
                                    : options.output_directory;
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) throw OutputError(directory, "cannot create the RAO directory", error.message());
  return directory;
}

std::vector<RaoChannel> parse_channels(const RaoOptions& options, const std::string& platform,
                                       const CaseDefinition& definition) {
  std::vector<RaoChannel> channels;
  if (options.channels.empty())
    for (const std::string& mode : platform_mode_names()) channels.push_back(parse_rao_channel(mode, platform));
  for (const std::string& text : options.channels) {
    channels.push_back(parse_rao_channel(text, platform));
    check_rao_channel(channels.back(), definition);
  }
  return channels;
}

int finish(const RaoOptions& options, const std::string& directory, const RaoTable& table, int exit_code) {
  write_rao_table(directory, table);
  if (!options.quiet) {
    print_comparison(table);
    if (!table.reference_note.empty()) fmt::print("  no frequency-domain RAO: {}\n", table.reference_note);
    fmt::print("wrote {0}/rao.h5, {0}/rao.csv\n", directory);  // scripts/plot_rao.py says where the figure went
  }
  if (options.plot) {
    const int plotted = draw_figure(directory);
    if (plotted != 0) {
      fmt::print(stderr, "heavesim: error: scripts/plot_rao.py exited with {}; rao.h5 and rao.csv are written\n", plotted);
      return exit_code == 0 ? 1 : exit_code;
    }
  }
  return exit_code;
}

int regular_sweep(const RaoOptions& options) {
  // Before anything touches HDF5: the workers are forked from this process.
  hdf5::skip_library_exit_cleanup();
  const std::unique_ptr<TaskDistribution> pool = make_process_pool(options.jobs);
  const std::vector<double> periods = parse_periods(options.periods);
  if (!(options.amplitude > 0.0) || !std::isfinite(options.amplitude))
    throw argument_error("--amplitude", fmt::format("{}", options.amplitude), "a wave amplitude a > 0 m");
  const CaseDefinition base = load_case(options.input, options.overrides);
  if (!base.waves.declared())
    throw base.error_at("waves", "no waves (or type: none)",
                        "a `waves:` block: its heading and ramp are kept, and each run's waves become regular waves "
                        "of one period and the --amplitude");
  const auto [excitation, platform] = wave_excitation_element(base);
  const std::vector<RaoChannel> channels = parse_channels(options, platform, base);
  const double window = base.solver.t_end - base.output.evaluate_after;
  const double longest = *std::max_element(periods.begin(), periods.end());
  if (window < longest)
    throw base.error_at("output.evaluate_after", fmt::format("a fitting window of {:.6g} s (output.evaluate_after to solver.t_end)", window),
                        fmt::format("at least the longest period, {:.6g} s (the fit is over the last whole cycles after "
                                    "output.evaluate_after; --set solver.t_end=... or output.evaluate_after=...)", longest));

  std::vector<std::vector<std::string>> run_overrides;
  for (double period : periods) {
    std::vector<std::string> overrides = options.overrides;
    overrides.push_back(regular_waves_override(base.waves, options.amplitude, period));
    if (const std::optional<std::string> output = output_channels_override(channels)) overrides.push_back(*output);
    load_case(options.input, overrides);  // refused overrides are bad input before anything runs
    run_overrides.push_back(std::move(overrides));
  }
  const std::string directory = output_directory(options);
  for (const char* folder : {"runs", "logs"}) std::filesystem::create_directories(std::filesystem::path(directory) / folder);
  const auto run_name = [&](std::size_t i) { return fmt::format("T{:.6g}", periods[i]); };

  const StopSignals signals;
  SweepProgress progress(static_cast<int>(periods.size()), !options.quiet);
  TaskCallbacks callbacks;
  callbacks.run = [&](int index, int worker) {
    const std::size_t i = static_cast<std::size_t>(index);
    RunRecord record;
    record.result_file = "runs/" + run_name(i) + ".h5";
    record.rank_or_worker = worker;
    RunOptions run;
    run.case_path = options.input;
    run.output_path = (std::filesystem::path(directory) / record.result_file).string();
    run.overrides = run_overrides[i];
    run.samples_beside = options.jobs == 1;  // runs side by side take a core each
    run_logged(run, (std::filesystem::path(directory) / "logs" / (run_name(i) + ".log")).string(), record);
    return encode(record);
  };
  callbacks.crashed = [&](int index, int worker, int signal) {
    RunRecord record;
    record.status = run_status::crashed;
    record.exit_code = 128 + signal;
    record.rank_or_worker = worker;
    record.result_file = "runs/" + run_name(static_cast<std::size_t>(index)) + ".h5";
    record.message = fmt::format("the worker running it was killed by signal {}", signal);
    return encode(record);
  };
  callbacks.finished = [&](int, const std::string& bytes) { progress.finished(decode(bytes)); };
  callbacks.stop_requested = [] { return StopSignals::received() != 0; };
  const std::vector<std::optional<std::string>> records = pool->run(static_cast<int>(periods.size()), callbacks);
  progress.clear();

  RaoTable table;
  table.method = "regular_sweep";
  table.source = options.input;
  table.platform = platform;
  table.heading = base.waves.heading;
  table.amplitude = options.amplitude;
  table.wave_elevation_channel = "/forces/" + excitation + "/wave_elevation";
  for (const RaoChannel& channel : channels) table.columns.push_back(empty_column(channel.name));
  int failed = 0;
  for (std::size_t i = 0; i < periods.size(); ++i) {
    const double w = 2 * M_PI / periods[i];
    table.angular_frequencies.push_back(w);
    const RunRecord record = records[i] ? decode(*records[i]) : RunRecord{};
    for (RaoColumn& column : table.columns) column.values.emplace_back(nan, nan);
    if (record.status != run_status::complete) {
      ++failed;
      table.notes.push_back(fmt::format("{}: {} {}", record.result_file, record.status, record.message));
      fmt::print(stderr, "heavesim: the run at T = {:.6g} s: {}: {}\n", periods[i], record.status, record.message);
      if (record.exit_code == 2) return 2;  // bad input is the same for every period
      continue;
    }
    table.notes.push_back(record.result_file);
    const std::string path = (std::filesystem::path(directory) / record.result_file).string();
    const hdf5::Reader file(path, "a heavesim result file");
    const RecordedTime axis = read_recorded_time(file, path, 8);
    // The last whole cycles after output.evaluate_after.
    const double start = file.number_attribute("/", "statistics_window_start").value_or(axis.time.front());
    const double cycles = std::floor((axis.time.back() - start) / periods[i] + 1e-9);
    const double from = axis.time.back() - cycles * periods[i] - 1e-9 * periods[i];
    const std::size_t first =
        static_cast<std::size_t>(std::lower_bound(axis.time.begin(), axis.time.end(), from) - axis.time.begin());
    const std::size_t n = axis.time.size() - first;
    const RaoChannel elevation_channel = parse_rao_channel(table.wave_elevation_channel, platform);
    const ChannelSeries elevation = read_rao_channel(file, path, elevation_channel, axis.time.size());
    const std::complex<double> eta = stats::fit_harmonic(&axis.time[first], &elevation.values[first], n, w);
    for (std::size_t c = 0; c < channels.size(); ++c) {
      const ChannelSeries series = read_rao_channel(file, path, channels[c], axis.time.size());
      table.columns[c].unit = per_wave_unit(series.unit);
      table.columns[c].values.back() = stats::fit_harmonic(&axis.time[first], &series.values[first], n, w) / eta;
    }
  }
  add_reference(table, channels, base);
  if (!options.quiet) {
    fmt::print("RAO of {} from a regular-wave sweep, a = {:.6g} m, heading {:.6g} deg, {} period(s) on {} worker(s){}\n",
               options.input, options.amplitude, base.waves.heading * 180 / M_PI, periods.size(), pool->size(),
               failed ? fmt::format(", {} failed", failed) : "");
    fmt::print("{:>8}", "T [s]");
    for (const RaoColumn& column : table.columns) fmt::print("  {:>22}", column.name + " [" + column.unit + ", deg]");
    fmt::print("\n");
    for (std::size_t r = 0; r < periods.size(); ++r) {
      fmt::print("{:>8.4g}", periods[r]);
      for (const RaoColumn& column : table.columns)
        fmt::print("  {:>13.5g} {:>8.2f}", std::abs(column.values[r]), std::arg(column.values[r]) * 180 / M_PI);
      fmt::print("\n");
    }
  }
  return finish(options, directory, table, failed ? 4 : 0);
}

int cross_spectral(const RaoOptions& options) {
  if (!options.periods.empty())
    throw argument_error("--periods", "'" + options.periods + "' with a result file",
                         "no --periods: the RAO of a result file comes from its own sea (H1); give a case file to sweep periods");
  const std::string& path = options.input;
  std::optional<hdf5::Reader> opened;
  try {
    opened.emplace(path, "a heavesim result file (HDF5)");
  } catch (const hydro::DataError& error) {
    throw InputError(SourceLocation{path, 0, 0}, "", error.found(), error.expected());
  }
  const hdf5::Reader& file = *opened;
  std::string case_path = options.case_path;
  if (case_path.empty()) {
    const std::optional<std::string> recorded = file.text_attribute("/", "case_file");
    if (!recorded)
      throw InputError(SourceLocation{path, 0, 0}, "case_file", "no case_file attribute", "a heavesim result file, or --case CASE.yaml");
    case_path = *recorded;
    // The run records the case path as it was given, relative to where the run was made.
    std::error_code ignored;
    if (!std::filesystem::exists(case_path, ignored))
      throw InputError(SourceLocation{path, 0, 0}, "case_file",
                       "the run's case file '" + case_path + "', which does not exist from " +
                           std::filesystem::current_path(ignored).string(),
                       "the directory the run was made from, or --case CASE.yaml");
  }
  const CaseDefinition definition = load_case(case_path, options.overrides);
  const auto [excitation, platform] = wave_excitation_element(definition);
  const std::vector<RaoChannel> channels = parse_channels(options, platform, definition);
  const RecordedTime axis = read_recorded_time(file, path, 8);
  const std::size_t samples = axis.time.size();

  RaoTable table;
  table.method = "h1";
  table.source = path;
  table.platform = platform;
  table.heading = definition.waves.heading;
  table.wave_elevation_channel = "/forces/" + excitation + "/wave_elevation";
  if (!file.has(table.wave_elevation_channel))
    throw InputError(SourceLocation{path, 0, 0}, table.wave_elevation_channel, "no such dataset",
                     "the incident wave elevation the run's wave_excitation '" + excitation +
                         "' records: run the case with `forces` in output.channels");
  const std::vector<double> elevation_all =
      read_rao_channel(file, path, parse_rao_channel(table.wave_elevation_channel, platform), samples).values;
  const double start = file.number_attribute("/", "statistics_window_start").value_or(axis.time.front());
  const std::size_t first = static_cast<std::size_t>(
      std::lower_bound(axis.time.begin(), axis.time.end(), start - 1e-9 * std::max(1.0, std::abs(start))) - axis.time.begin());
  const std::size_t n = samples - std::min(first, samples);
  int segment = 0;
  if (options.segment > 0.0) {
    segment = 2 * static_cast<int>(std::lround(options.segment / axis.step / 2));
  } else {
    for (segment = 16; static_cast<std::size_t>(2 * segment) <= n / 8; segment *= 2) {
    }
  }
  if (segment < 16 || static_cast<std::size_t>(segment) > n)
    throw argument_error(options.segment > 0 ? "--segment" : path,
                         fmt::format("a segment of {} samples for a window of {} samples (t >= {:.6g} s, step {:.6g} s)",
                                     segment, n, start, axis.step),
                         "a Welch segment of at least 16 samples within the evaluation window (about an eighth of it "
                         "gives 15 half-overlapping segments)");
  const std::vector<double> elevation(elevation_all.begin() + static_cast<std::ptrdiff_t>(first), elevation_all.end());
  const double fs = 1.0 / axis.step;

  std::vector<std::size_t> bins;
  for (std::size_t c = 0; c < channels.size(); ++c) {
    const ChannelSeries series = read_rao_channel(file, path, channels[c], samples);
    const std::vector<double> output(series.values.begin() + static_cast<std::ptrdiff_t>(first), series.values.end());
    const stats::CrossSpectralEstimate estimate = stats::cross_spectral_density(elevation, output, segment, fs);
    if (c == 0) {
      // The sea's band: bins holding at least 1 % of the elevation's peak density.
      const double peak = *std::max_element(estimate.input_density.begin(), estimate.input_density.end());
      for (std::size_t k = 1; k < estimate.frequencies.size(); ++k)
        if (estimate.input_density[k] >= 0.01 * peak) {
          bins.push_back(k);
          table.angular_frequencies.push_back(2 * M_PI * estimate.frequencies[k]);
        }
      for (const RaoChannel& channel : channels) table.columns.push_back(empty_column(channel.name));
    }
    table.columns[c].unit = per_wave_unit(series.unit);
    for (std::size_t k : bins) {
      table.columns[c].values.push_back(estimate.transfer_function(k));
      table.columns[c].coherence.push_back(estimate.coherence(k));
    }
  }
  add_reference(table, channels, definition);
  if (!options.quiet)
    fmt::print("RAO of {} by H1 = G_xy / G_xx: input {}, window {:.6g} .. {:.6g} s, segments of {} samples ({:.6g} s, "
               "half-overlapping, Hann), {} bins in the sea's band\n",
               path, table.wave_elevation_channel, axis.time[first], axis.time.back(), segment, segment * axis.step,
               bins.size());
  return finish(options, output_directory(options), table, 0);
}

}  // namespace

int rao_command(const RaoOptions& options) {
  const std::string extension = std::filesystem::path(options.input).extension().string();
  if (extension == ".h5" || extension == ".hdf5") return cross_spectral(options);
  if (options.periods.empty())
    throw argument_error("--periods", "none", "the sweep's wave periods in s: --periods A:STEP:B or T1,T2,...");
  return regular_sweep(options);
}

}  // namespace heavesim
