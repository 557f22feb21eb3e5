// The heap on huge pages (cli/process_memory.hpp), checked against what the kernel reports
// of the process's mappings (/proc/self/maps and smaps), not against our own arithmetic.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli/process_memory.hpp"

namespace heavesim {
namespace {

/// The mapping of /proc/self/smaps that holds `address`: its name ("[heap]", a file,
/// or "" for an anonymous mapping) and its THPeligible field (-1 if absent).
struct ProcessMapping {
  bool found = false;
  std::string name;
  int huge_page_eligible = -1;
};

ProcessMapping process_mapping_of(const void* pointer) {
  const auto address = reinterpret_cast<std::uintptr_t>(pointer);
  std::ifstream smaps("/proc/self/smaps");
  ProcessMapping mapping;
  bool inside = false;
  for (std::string line; std::getline(smaps, line);) {
    std::istringstream fields(line);
    std::string first;
    fields >> first;
    const std::size_t dash = first.find('-');
    const bool header = dash != std::string::npos && first.find(':') == std::string::npos;
    if (header) {
      if (inside) return mapping;
      const std::uintptr_t begin = std::stoull(first.substr(0, dash), nullptr, 16);
      const std::uintptr_t end = std::stoull(first.substr(dash + 1), nullptr, 16);
      inside = begin <= address && address < end;
      if (inside) {
        std::string permissions, offset, device, inode;
        fields >> permissions >> offset >> device >> inode;
        mapping.found = true;
        std::getline(fields >> std::ws, mapping.name);
      }
    } else if (inside && first == "THPeligible:") {
      fields >> mapping.huge_page_eligible;
    }
  }
  return mapping;
}

bool transparent_huge_pages_offered() {
  std::ifstream setting("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string text;
  std::getline(setting, text);
  return text.find("[always]") != std::string::npos || text.find("[madvise]") != std::string::npos;
}

TEST(ProcessMemory, EveryThreadsBlocksComeFromTheAdvisedHeap) {
  back_heap_with_huge_pages();
  // Blocks as the result file's (a series' block of 1024 rows: 8-48 KiB) and larger ones
  // (200 KiB: above glibc's default mmap threshold of 128 KiB), 8 MiB in all, from this
  // thread and from a second one (the recorder's helpers allocate there).
  std::vector<void*> blocks;
  for (int i = 0; i < 96; ++i) blocks.push_back(std::malloc(i % 3 == 0 ? 200 << 10 : 48 << 10));
  void* from_second_thread = nullptr;
  std::thread([&] { from_second_thread = std::malloc(64 << 10); }).join();
  blocks.push_back(from_second_thread);
  for (void* block : blocks) {
    ASSERT_NE(block, nullptr);
    const ProcessMapping mapping = process_mapping_of(block);
    ASSERT_TRUE(mapping.found);
    // Without the call, the 200 KiB blocks would be mappings of their own and the second
    // thread's block in an arena of its own: neither is "[heap]".
    EXPECT_EQ(mapping.name, "[heap]") << "block " << block;
  }
  // The heap's part past the advice's start (the last blocks) may be backed by huge pages.
  if (transparent_huge_pages_offered()) {
    EXPECT_EQ(process_mapping_of(blocks[blocks.size() - 2]).huge_page_eligible, 1);
    EXPECT_EQ(process_mapping_of(from_second_thread).huge_page_eligible, 1);
  }
  for (void* block : blocks) std::free(block);
}

}  // namespace
}  // namespace heavesim
