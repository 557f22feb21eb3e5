// The WAMIT text readers (.1, .3, .hst): the same bytes through all three.
#include "fuzz/fuzz_bem_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  heavesim::fuzz::read_bem_file_every_way(data, size, "fuzz.wamit", "fuzz_wamit");
  return 0;
}
