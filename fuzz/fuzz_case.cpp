// The case reader: bytes -> a YAML case file -> load_case -> build_scene.
// The bytes may hold up to three parts, cut at lines that are exactly "#%%":
//   1. the case file (cases/fuzz/case.yaml in the scratch tree, so that the seeds'
//      relative includes and data files resolve),
//   2. --set overrides, one per line,
//   3. a second file, cases/fuzz/part.yaml, which the case may include.
// The contract (docs/case-format.md): bad input is an InputError; a case whose loops do
// not assemble is a NumericalError (exit 3). Anything else -- another exception, a
// crash, a sanitizer report, a timeout, running out of memory -- is a finding.
#include "app/case/case_definition.hpp"
#include "app/scene/scene.hpp"
#include "fuzz/fuzz_support.hpp"
#include "kernel/math/numerical_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace heavesim;
  const std::vector<std::string_view> parts = fuzz::split_at_marker_lines(fuzz::as_text(data, size), "#%%");
  const std::filesystem::path& directory = fuzz::scratch_directory();
  const std::filesystem::path case_path = directory / "case.yaml", part_path = directory / "part.yaml";
  fuzz::write_file(case_path, parts[0]);
  std::vector<std::string> overrides;
  if (parts.size() > 1)
    for (std::string_view line : fuzz::lines(parts[1])) overrides.emplace_back(line);
  if (parts.size() > 2)
    fuzz::write_file(part_path, parts[2]);
  else
    std::filesystem::remove(part_path);
  try {
    const CaseDefinition definition = load_case(case_path.string(), overrides);
    const Scene scene = build_scene(definition);
  } catch (const InputError&) {
  } catch (const NumericalError&) {
  } catch (...) {
    fuzz::report_unexpected_exception("fuzz_case");
  }
  return 0;
}
