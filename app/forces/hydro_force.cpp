#include "app/forces/hydro_force.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "app/scene/recorded_load.hpp"
#include "app/scene/scene_build_context.hpp"
#include "hydro/data_file.hpp"

namespace heavesim {

hydro::Matrix6 read_matrix6(const NodeReader& reader) {
  const char* expected = "6 rows of 6 numbers, or 6 numbers (the diagonal), WAMIT order [surge, sway, heave, roll, "
                         "pitch, yaw]";
  if (!reader.node().is_sequence()) reader.fail(expected);
  const std::vector<NodeReader> items = reader.items();
  if (items.size() != 6) reader.fail(fmt::format("{} entries", items.size()), expected);
  hydro::Matrix6 matrix = hydro::Matrix6::Zero();
  if (items[0].node().is_scalar()) {
    for (int i = 0; i < 6; ++i) matrix(i, i) = items[i].number();
    return matrix;
  }
  for (int i = 0; i < 6; ++i) {
    const std::vector<double> row = items[i].node().is_sequence() ? items[i].numbers() : std::vector<double>{};
    if (row.size() != 6) items[i].fail("a row of 6 numbers");
    for (int j = 0; j < 6; ++j) matrix(i, j) = row[j];
  }
  return matrix;
}

hydro::Vector6 read_vector6(const NodeReader& reader) {
  const std::vector<double> values = reader.node().is_sequence() ? reader.numbers() : std::vector<double>{};
  if (values.size() != 6) reader.fail("6 numbers in WAMIT order [surge, sway, heave, roll, pitch, yaw]");
  return Eigen::Map<const hydro::Vector6>(values.data());
}

void check_symmetric_positive(const NodeReader& reader, const hydro::Matrix6& matrix, const std::string& what) {
  if (!matrix.isApprox(matrix.transpose(), 1e-9) && !matrix.isZero())
    reader.fail("a matrix that is not symmetric", "a symmetric " + what + " matrix");
  if ((matrix.diagonal().array() < 0.0).any())
    reader.fail("a negative diagonal entry", "a " + what + " matrix with diagonal entries >= 0");
}

namespace {

std::string read_path(const NodeReader& reader) {
  const std::string text = reader.text();
  std::filesystem::path path(text);
  if (path.is_relative()) path = std::filesystem::path(reader.location().file).parent_path() / path;
  // What the path names, said at the key (a FIFO, a device, a directory, too large);
  // the readers check again (hydro/data_file.hpp) for callers that are not a case.
  if (const std::string problem = hydro::unreadable_file(path.string(), hydro::max_data_file_bytes); !problem.empty())
    reader.fail(fmt::format("'{}', {} ({})", text, problem, path.string()),
                fmt::format("a readable data file (a regular file of at most {} bytes), relative to the case file",
                            hydro::max_data_file_bytes));
  return path.lexically_normal().string();
}

}  // namespace

HydroDataFile read_data_file(const NodeReader& item, const std::string& file_key, bool mesh) {
  HydroDataFile file;
  file.key = file_key;
  if (!file_key.empty()) file.path = read_path(item[file_key]);
  if (auto scale = item.optional("length_scale")) {
    // ULEN nondimensionalises WAMIT's files only; BEMIO and Capytaine store SI values.
    if (!mesh && bem::bem_file_format(file.path) != bem::BemFileFormat::wamit)
      scale->fail("'length_scale' with a BEMIO (.h5) or Capytaine (.nc) file",
                  "no 'length_scale' (only WAMIT files are nondimensional in ULEN)");
    file.length_scale = scale->positive_number();
  }
  return file;
}

bem::WamitScaling wamit_scaling(const CaseDefinition& definition, double length_scale) {
  return {definition.water.density, definition.gravity.norm(), length_scale};
}

void throw_data_error(const CaseDefinition& definition, const std::string& name, const std::string& key,
                      const hydro::DataError& error) {
  const std::string where = error.line() > 0 ? fmt::format("{}:{}", error.file(), error.line()) : error.file();
  throw definition.item_error(name, key, error.found() + " (in " + where + ")", error.expected());
}

int floating_body_link(const SceneBuildContext& context, const std::string& name, const std::string& body) {
  const int link = context.model.link_index(body);
  if (body == ModelBuilder::ground_name || link < 0)
    throw context.error(name, "body", "'" + body + "', which is not a body", "the name of a floating body");
  return link;
}

void add_hydro_element(SceneBuildContext& context, const std::string& name, const std::string& body,
                       const std::function<std::unique_ptr<ForceElement>(int link)>& make,
                       std::shared_ptr<const hydro::WaveTrain> recorded_waves) {
  const int link = floating_body_link(context, name, body);
  std::unique_ptr<ForceElement> element;
  try {
    element = make(link);
  } catch (const ParameterError& error) {
    throw to_input_error(context.definition, context.definition.item_paths.at(name), error);
  }
  context.system.add_force_element(
      std::make_unique<RecordedLoad>(std::move(element), context.model, link, std::move(recorded_waves)));
}

}  // namespace heavesim
