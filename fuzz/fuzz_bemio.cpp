// The BEMIO HDF5 reader (.h5): mutated HDF5 files.
#include "fuzz/fuzz_bem_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  heavesim::fuzz::read_bem_file_every_way(data, size, "fuzz.h5", "fuzz_bemio");
  return 0;
}
