#pragma once
// The main thread's heap backed by 2 MiB pages (Linux transparent huge pages), for a
// process that is about to build hundreds of megabytes of small objects and exit:
// `lagrangelab derive`. The expanded Panda's derivation and display trees touch 150–300
// MB; on this platform (a virtual machine) every first touch of a 4 KiB page is a fault
// that cost a fifth to a quarter of the printing time (perf: exc_page_fault under the
// display builder). With THP set to "madvise" (Debian's default) only memory that asks
// for it gets huge pages; glibc asks only when GLIBC_TUNABLES=glibc.malloc.hugetlb=1 is
// in the environment at start.
//
// What it does: mallopt keeps allocations below 32 MiB in the heap (not mmap) and the
// heap's top from being trimmed; the heap is grown once by `reserve` bytes of address
// space (nothing is touched: no memory is used until it is), advised MADV_HUGEPAGE,
// and given back to malloc. Everything the main thread allocates after that lands in
// the advised range until it is used up; beyond it the heap grows as before.
//
// For short-lived command-line processes only: the heap never shrinks afterwards, and a
// window that runs for hours should return memory to the system.
#include <cstddef>

namespace ll {

struct HugePageHeap {
    bool advised = false;         // madvise succeeded on the range
    std::size_t reservedBytes = 0;  // the advised range's length
    const char* reason = "";        // why not, when not advised
};

// Call early, on the main thread, before the work (`reserve` is at most 1 GiB); a later
// call returns the first call's result. Never throws; when THP is "never", sbrk cannot
// grow the heap or madvise fails, nothing changes but the two mallopt settings (none at
// all with THP "never").
HugePageHeap useHugePagesForHeap(std::size_t reserve = std::size_t(1) << 30);

}  // namespace ll
