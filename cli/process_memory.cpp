#include "cli/process_memory.hpp"

#if defined(__GLIBC__) && defined(__linux__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#endif

namespace heavesim {

void back_heap_with_huge_pages() {
#if defined(__GLIBC__) && defined(__linux__)
  constexpr std::uintptr_t huge_page = std::uintptr_t{2} << 20;
  constexpr int heap_step = 64 << 20;
  // One arena: the helper threads' allocations (the recorder's, HDF5's on the block
  // writer) come from the advised heap too, not from 64 MiB arenas of their own. They share
  // its lock; the integration's step allocates nothing (tests/kernel/test_no_heap_allocation.cpp)
  // and the helpers allocate a little per block, so it is rarely contended.
  // Blocks below 32 MiB (the largest threshold 64-bit glibc takes; a setting turns off its
  // dynamic threshold) from the heap rather than a mapping of their own, which would be
  // faulted in page by page and returned at every free. Nothing more if glibc refuses one.
  const bool configured = mallopt(M_ARENA_MAX, 1) == 1 && mallopt(M_MMAP_THRESHOLD, 32 << 20) == 1 &&
                          mallopt(M_TOP_PAD, heap_step) == 1 && mallopt(M_TRIM_THRESHOLD, 2 * heap_step) == 1;
  if (!configured) return;
  // Growing the heap once places the next 64 MiB (the top pad) behind the break; the
  // block's address is where the heap's free top begins (whether or not it grew).
  void* volatile grow = std::malloc(huge_page);  // volatile: a malloc/free pair the compiler may drop
  const auto top = reinterpret_cast<std::uintptr_t>(grow);
  const auto end = reinterpret_cast<std::uintptr_t>(sbrk(0));
  std::free(grow);
  // Only whole, aligned 2 MiB ranges can be huge pages.
  const std::uintptr_t first = (top + huge_page - 1) & ~(huge_page - 1), last = end & ~(huge_page - 1);
  if (top != 0 && top < end && first < last)
    madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);  // a refusal leaves 4 KiB pages
#endif
}

}  // namespace heavesim
