// The heap on huge pages (cli/process_memory.hpp), checked against what the kernel reports
// of the process's mappings (/proc/self/smaps), not against our own arithmetic.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli/process_memory.hpp"

namespace heavesim {
namespace {

/// The mapping of /proc/self/smaps that holds `address`: its name ("[heap]", a file, or ""
/// for an anonymous mapping) and its VmFlags ("hg": advised MADV_HUGEPAGE).
struct ProcessMapping {
  bool found = false;
  std::string name, flags;
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
    } else if (inside && first == "VmFlags:") {
      std::getline(fields >> std::ws, mapping.flags);
    }
  }
  return mapping;
}

/// What is wrong with the heap after back_heap_with_huge_pages(), "" if nothing: blocks as
/// the result file's (a series' block of 1024 rows, 8-48 KiB) and larger ones (200 KiB,
/// above glibc's default mmap threshold of 128 KiB), 9.25 MiB in all, from this thread and
/// one from a second thread (the recorder's helpers allocate there), must lie in "[heap]";
/// where the kernel has transparent huge pages, the last ones in a range advised for them.
std::string heap_advice_problems() {
  back_heap_with_huge_pages();
  std::vector<void*> blocks;
  for (int i = 0; i < 96; ++i) blocks.push_back(std::malloc(i % 3 == 0 ? 200 << 10 : 48 << 10));
  void* from_second_thread = nullptr;
  std::thread([&] { from_second_thread = std::malloc(64 << 10); }).join();
  blocks.push_back(from_second_thread);
  std::ostringstream problems;
  for (void* block : blocks) {
    const ProcessMapping mapping = process_mapping_of(block);
    // Without the call the 200 KiB blocks would be mappings of their own and the second
    // thread's block in an arena of its own: neither is "[heap]".
    if (!mapping.found || mapping.name != "[heap]")
      problems << "block " << block << " in mapping '" << mapping.name << "', not [heap]\n";
  }
  struct stat transparent_huge_pages {};
  if (stat("/sys/kernel/mm/transparent_hugepage", &transparent_huge_pages) == 0) {
    // "hg" records the advice itself, whatever the system's policy (always, madvise, a
    // process with huge pages disabled).
    const std::vector<const void*> last_blocks = {blocks[blocks.size() - 2], from_second_thread};
    for (const void* block : last_blocks) {
      const ProcessMapping mapping = process_mapping_of(block);
      if ((" " + mapping.flags + " ").find(" hg ") == std::string::npos)
        problems << "block " << block << " in a range not advised for huge pages (VmFlags: " << mapping.flags << ")\n";
    }
  }
  for (void* block : blocks) std::free(block);
  return problems.str();
}

TEST(ProcessMemory, EveryThreadsBlocksComeFromTheAdvisedHeap) {
  // In a fresh process (the binary run again for this test alone): the call changes malloc
  // for the whole process, and a process whose threads already made arenas of their own
  // would hand the second thread one of those.
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        const std::string problems = heap_advice_problems();
        std::fputs(problems.c_str(), stderr);
        std::exit(problems.empty() ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace heavesim
