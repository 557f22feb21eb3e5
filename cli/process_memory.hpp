#pragma once
// The process's heap on transparent huge pages (2 MiB), where the kernel offers them.
//
// Why: a run touches tens of MiB of fresh memory (the result file's blocks and staging,
// the statistics' windows, HDF5's metadata), and on a virtual machine every first touch
// of a 4 KiB page is a fault costing ~12 us (docs/performance.md, "Issue #18, sixteenth
// round": the drilling case took ~4,800 faults, a third of its system time). A 2 MiB page
// is one fault for what were 512.

namespace heavesim {

/// Has glibc's malloc serve every thread from the main heap, blocks up to 32 MiB
/// included, growing it 64 MiB at a time and never trimming it below 128 MiB, and
/// advises the kernel (madvise MADV_HUGEPAGE) to back the heap's next 64 MiB with huge
/// pages: what glibc itself does when the environment says
/// GLIBC_TUNABLES=glibc.malloc.hugetlb=1 (glibc 2.35 and later), from inside the process.
/// Call first in main(), before any thread starts. An advice, not a requirement: where
/// there is no glibc, or transparent huge pages are off, memory is as before.
void back_heap_with_huge_pages();

}  // namespace heavesim
