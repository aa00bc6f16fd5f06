#include "core/io/huge_page_heap.hpp"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

namespace ll {

namespace {

// madvise(MADV_HUGEPAGE) succeeds with THP "never" too (only a kernel without THP
// refuses it): what the kernel will do is read here.
bool hugePagesOff() {
    std::ifstream enabled("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string mode;
    std::getline(enabled, mode);
    return mode.empty() || mode.find("[never]") != std::string::npos;
}

HugePageHeap reserveHugePageHeap(std::size_t reserve) {
    HugePageHeap out;
    if (hugePagesOff()) {
        out.reason = "transparent huge pages are off (/sys/kernel/mm/transparent_hugepage/enabled: never)";
        return out;
    }
    reserve = std::min<std::size_t>(reserve, INT_MAX / 2);
    // glibc's largest mmap threshold (HEAP_MAX_SIZE / 2 on 64-bit): blocks below it come
    // from the heap, so the big document strings are in the advised range too.
    constexpr std::size_t threshold = std::size_t(32) << 20;
    // The trim threshold above the reservation: freed back at the end, the reserved blocks
    // make one free top chunk that free() would otherwise give back to the system at once,
    // advice and all.
    if (!mallopt(M_MMAP_THRESHOLD, static_cast<int>(threshold)) || !mallopt(M_TRIM_THRESHOLD, INT_MAX)) {
        out.reason = "mallopt refused the thresholds";
        return out;
    }
    constexpr std::size_t hugePage = std::size_t(2) << 20;
    constexpr std::size_t block = threshold - hugePage;  // each block below the threshold: heap, not mmap
    char* const before = static_cast<char*>(sbrk(0));
    std::vector<void*> blocks;
    blocks.reserve(reserve / block + 1);
    for (std::size_t taken = 0; taken < reserve; taken += block) {
        void* p = std::malloc(block);
        if (!p) break;
        blocks.push_back(p);
    }
    // The heap grew: from the first block (cut from the free top the heap had, below
    // `before`) to the new end is free heap. What lies below it stays in small pages.
    char* const after = static_cast<char*>(sbrk(0));
    char* const low = blocks.empty() ? before : std::min(before, static_cast<char*>(blocks.front()));
    const auto start = (reinterpret_cast<std::uintptr_t>(low) + hugePage - 1) & ~(hugePage - 1);
    const auto end = reinterpret_cast<std::uintptr_t>(after) & ~(hugePage - 1);
    if (after <= before || end <= start) {
        out.reason = "the heap could not be grown (sbrk)";
    } else if (madvise(reinterpret_cast<void*>(start), end - start, MADV_HUGEPAGE) != 0) {
        out.reason = "madvise(MADV_HUGEPAGE) failed: this kernel has no transparent huge pages";
    } else {
        out.advised = true;
        out.reservedBytes = end - start;
    }
    // Back to malloc as one free top chunk; the trim threshold keeps it in the heap.
    for (auto it = blocks.rbegin(); it != blocks.rend(); ++it) std::free(*it);
    return out;
}

}  // namespace

HugePageHeap useHugePagesForHeap(std::size_t reserve) {
    // Once per process: a second call would find the first's free range and not grow.
    static std::mutex once;
    static std::optional<HugePageHeap> done;
    const std::lock_guard lock(once);
    if (done) return *done;
    done = reserveHugePageHeap(reserve);
    return *done;
}

}  // namespace ll
