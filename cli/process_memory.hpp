#pragma once
// The process's heap on transparent huge pages (2 MiB), where the kernel offers them.
//
// Why: a run touches tens of MiB of fresh memory (the result file's blocks and staging,
// the statistics' windows, HDF5's metadata), and on a virtual machine every first touch
// of a 4 KiB page is a fault costing ~12 us (docs/performance.md, "Issue #18, sixteenth
// round": the drilling case took ~4,800 faults). A 2 MiB page is one fault for what were 512.
//
// The price: a 2 MiB page is resident whole once touched, and the kernel's khugepaged may
// collapse a sparsely used advised range into one, so a process may hold up to the advised
// 64 MiB more than it uses; with the kernel's default `defrag` setting (madvise) a fault in
// the advised range may compact memory to find a huge page.

namespace heavesim {

/// Has glibc's malloc (64-bit) serve every thread from the main heap, blocks below 32 MiB
/// included, growing it 64 MiB at a time and trimming its free top only beyond 128 MiB, and
/// advises the kernel (madvise MADV_HUGEPAGE) to back the heap's next 64 MiB with huge
/// pages: close to what glibc itself does when the environment says
/// GLIBC_TUNABLES=glibc.malloc.hugetlb=1 (glibc 2.35 and later), which advises every
/// extension of the heap. Call first in main(), before any thread starts. An advice, not a
/// requirement: where there is no 64-bit glibc, or transparent huge pages are off, memory
/// is as before.
void back_heap_with_huge_pages();

}  // namespace heavesim
