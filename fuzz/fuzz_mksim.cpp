// The MKSim model reader and its conversion to a case (app/mksim/): the bytes are a
// model file's text; a model that parses is also converted to YAML.
// The contract (app/mksim/mksim_reader.hpp): every malformed model is an InputError.
// Anything else is a finding.
#include "app/case/input_error.hpp"
#include "app/mksim/mksim_reader.hpp"
#include "app/mksim/mksim_to_case.hpp"
#include "fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace heavesim;
  try {
    const mksim::Model model = mksim::parse_model(std::string(fuzz::as_text(data, size)), "fuzz.mks");
    mksim::count(model).summary();
    mksim::to_case_yaml(model);
  } catch (const InputError&) {
  } catch (...) {
    fuzz::report_unexpected_exception("fuzz_mksim");
  }
  return 0;
}
