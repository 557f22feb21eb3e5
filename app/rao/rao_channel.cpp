#include "app/rao/rao_channel.hpp"

#include <cmath>
#include <regex>
#include <stdexcept>

#include <Eigen/Geometry>
#include <fmt/format.h>

#include "app/case/case_definition.hpp"

namespace heavesim {
namespace {

constexpr const char* channel_forms =
    "surge, sway, heave, roll, pitch, yaw, /bodies/<body>/point(x, y, z)[0..2], or a result path with its column "
    "for a multi-column dataset (/joints/<joint>/reaction_force[2], /forces/<element>/stroke)";

InputError bad_channel(const std::string& text, const std::string& expected) {
  return InputError(SourceLocation{"--channel", 0, 0}, "", "'" + text + "'", expected);
}

InputError missing(const std::string& file_path, const RaoChannel& channel, const std::string& dataset,
                   const std::string& found, const std::string& expected) {
  return InputError(SourceLocation{file_path, 0, 0}, dataset, found + " (channel '" + channel.name + "')", expected);
}

hdf5::Array read_series(const hdf5::Reader& file, const std::string& file_path, const RaoChannel& channel,
                        const std::string& dataset, std::size_t samples, std::size_t columns_needed,
                        const std::string& record_hint) {
  if (!file.has(dataset))
    throw missing(file_path, channel, dataset, "no such dataset",
                  "a recorded channel (" + record_hint + "; `heavesim stats " + file_path + "` lists what was recorded)");
  hdf5::Array data;
  try {
    data = file.read(dataset);
  } catch (const hydro::DataError& error) {
    throw missing(file_path, channel, dataset, error.found(), error.expected());
  }
  const std::size_t columns = data.shape.size() == 2 ? data.shape[1] : 1;
  if (data.shape.empty() || data.shape.size() > 2 || data.shape[0] < samples || columns < columns_needed)
    throw missing(file_path, channel, dataset, "shape " + hdf5::shape_text(data.shape),
                  fmt::format("a time series of {} rows and at least {} column(s)", samples, columns_needed));
  return data;
}

}  // namespace

const std::vector<std::string>& platform_mode_names() {
  static const std::vector<std::string> names = {"surge", "sway", "heave", "roll", "pitch", "yaw"};
  return names;
}

RaoChannel parse_rao_channel(const std::string& text, const std::string& platform) {
  RaoChannel channel;
  channel.name = text;
  const std::vector<std::string>& modes = platform_mode_names();
  for (int mode = 0; mode < 6; ++mode)
    if (text == modes[static_cast<std::size_t>(mode)]) {
      channel.mode = mode;
      channel.body = platform;
      return channel;
    }
  static const std::regex point(R"(/?bodies/([^/]+)/point\(\s*([^,\s]+)\s*,\s*([^,\s]+)\s*,\s*([^,\s\)]+)\s*\)\[([0-2])\])");
  static const std::regex series(R"((/?(bodies|joints|forces|signals|constraints|drivers)/[A-Za-z0-9_./-]*[A-Za-z0-9_])(\[([0-9]{1,4})\])?)");
  std::smatch match;
  if (std::regex_match(text, match, point)) {
    channel.point = true;
    channel.body = match[1].str();
    for (int k = 0; k < 3; ++k) {
      try {
        std::size_t used = 0;
        const std::string number = match[2 + k].str();
        channel.point_in_body[k] = std::stod(number, &used);
        if (used != number.size() || !std::isfinite(channel.point_in_body[k])) throw std::invalid_argument(number);
      } catch (const std::exception&) {
        throw bad_channel(text, "a point given by three numbers in m, body frame: /bodies/<body>/point(x, y, z)[c]");
      }
    }
    channel.column = std::stoi(match[5].str());
    channel.dataset = "/bodies/" + channel.body + "/position";
    return channel;
  }
  if (std::regex_match(text, match, series) && text.find("..") == std::string::npos) {
    channel.dataset = match[1].str().starts_with('/') ? match[1].str() : "/" + match[1].str();
    if (match[4].matched) channel.column = std::stoi(match[4].str());
    return channel;
  }
  throw bad_channel(text, channel_forms);
}

void check_rao_channel(const RaoChannel& channel, const CaseDefinition& definition) {
  if (channel.dataset.empty()) return;  // a mode: of the platform the case names
  const std::string path = channel.dataset.substr(1);  // "joints/platform/reaction_force"
  const std::size_t slash = path.find('/'), next = path.find('/', slash + 1);
  const std::string group = path.substr(0, slash), item = path.substr(slash + 1, next - slash - 1);
  if (group == "signals") return;
  const bool body = group == "bodies";
  const std::map<std::string, std::string>& names = body ? definition.body_paths : definition.item_paths;
  if (names.count(item)) return;
  std::string known;
  for (const auto& [name, key_path] : names)
    if (body || key_path.starts_with(group == "drivers" ? "drivers" : group == "constraints" ? "constraints" : group))
      known += (known.empty() ? "" : ", ") + name;
  throw bad_channel(channel.name, fmt::format("a channel of the case: no {} '{}' in it (it has: {})", body ? "body" : group, item,
                                              known.empty() ? "none" : known));
}

ChannelSeries read_rao_channel(const hdf5::Reader& file, const std::string& file_path, const RaoChannel& channel,
                               std::size_t samples) {
  ChannelSeries series;
  series.values.resize(samples);
  if (channel.mode >= 0 || channel.point) {
    const std::string hint = "output.channels with `bodies`";
    const std::string base = "/bodies/" + channel.body;
    const hdf5::Array position = read_series(file, file_path, channel, base + "/position", samples, 3, hint);
    const bool translation = channel.mode >= 0 && channel.mode < 3;
    if (translation) {
      for (std::size_t i = 0; i < samples; ++i) series.values[i] = position.values[3 * i + static_cast<std::size_t>(channel.mode)];
      series.unit = "m";
      return series;
    }
    const hdf5::Array orientation = read_series(file, file_path, channel, base + "/orientation", samples, 4, hint);
    for (std::size_t i = 0; i < samples; ++i) {
      const double* q = &orientation.values[4 * i];
      const Eigen::Quaterniond rotation = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized();
      if (channel.point) {
        const Vector3 p = Eigen::Map<const Vector3>(&position.values[3 * i]) + rotation * channel.point_in_body;
        series.values[i] = p[channel.column];
      } else {
        // Rotation vector (angle x axis, world axes): roll, pitch, yaw for small angles.
        const Eigen::AngleAxisd angle_axis(rotation);
        series.values[i] = angle_axis.angle() * angle_axis.axis()[channel.mode - 3] * 180.0 / M_PI;
      }
    }
    series.unit = channel.point ? "m" : "deg";
    return series;
  }
  const std::string hint = "output.channels with the group it belongs to (joints, reactions, forces, energy)";
  const std::size_t needed = channel.column < 0 ? 1 : static_cast<std::size_t>(channel.column) + 1;
  const hdf5::Array data = read_series(file, file_path, channel, channel.dataset, samples, needed, hint);
  const std::size_t columns = data.shape.size() == 2 ? data.shape[1] : 1;
  if (channel.column < 0 && columns > 1)
    throw missing(file_path, channel, channel.dataset, fmt::format("{} columns and no column given", columns),
                  fmt::format("one of its columns: {}[0] .. {}[{}]", channel.dataset, channel.dataset, columns - 1));
  const std::size_t column = channel.column < 0 ? 0 : static_cast<std::size_t>(channel.column);
  for (std::size_t i = 0; i < samples; ++i) series.values[i] = data.values[i * columns + column];
  series.unit = file.text_attribute(channel.dataset, "units").value_or("-");
  return series;
}

}  // namespace heavesim
