#include "core/io/huge_page_heap.hpp"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <optional>
#include <string_view>

#include <fcntl.h>
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

namespace ll {

namespace {

// madvise(MADV_HUGEPAGE) succeeds with THP "never" too (only a kernel without THP
// refuses it): what the kernel will do is read here (open/read: an ifstream's first use
// costs more than the whole reservation).
bool hugePagesOff() {
    const int fd = ::open("/sys/kernel/mm/transparent_hugepage/enabled", O_RDONLY | O_CLOEXEC);
    if (fd < 0) return true;
    char mode[128];
    const ssize_t n = ::read(fd, mode, sizeof mode - 1);
    ::close(fd);
    if (n <= 0) return true;
    return std::string_view(mode, static_cast<std::size_t>(n)).find("[never]") != std::string_view::npos;
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
    // The trim threshold above the reservation: freed back at the end, the reserved range
    // is one free top chunk that free() would otherwise give back to the system at once,
    // advice and all.
    if (!mallopt(M_MMAP_THRESHOLD, static_cast<int>(threshold)) || !mallopt(M_TRIM_THRESHOLD, INT_MAX)) {
        out.reason = "mallopt refused the thresholds";
        return out;
    }
    // One sbrk: with the top pad at `reserve`, a block larger than all free memory (no
    // free chunk can hold it) grows the heap by the block and the pad at once (growing it
    // block by block, 34 sbrk calls for 1 GiB, took 1-2 ms here).
    char* const before = static_cast<char*>(sbrk(0));
    constexpr std::size_t hugePage = std::size_t(2) << 20;
    if (!mallopt(M_TOP_PAD, static_cast<int>(reserve + 2 * hugePage))) {
        out.reason = "mallopt refused the top pad";
        return out;
    }
    const std::size_t request = mallinfo2().fordblks + 64;  // a few hundred KiB at the start
    void* const block = request < threshold ? std::malloc(request) : nullptr;
    mallopt(M_TOP_PAD, 128 * 1024);  // glibc's default again
    char* const after = static_cast<char*>(sbrk(0));
    // malloc wrote the new free top's header just past the block. A 2 MiB range with one
    // small page in it stays in small pages, so the advice starts at the first 2 MiB
    // boundary above everything touched; below it (under 2 MiB) stays in small pages.
    const auto touched = reinterpret_cast<std::uintptr_t>(block) + request + 64;
    const auto start = (touched + hugePage - 1) & ~(hugePage - 1);
    const auto end = reinterpret_cast<std::uintptr_t>(after) & ~(hugePage - 1);
    if (!block || after <= before || end <= start) {
        out.reason = "the heap could not be grown (sbrk)";
    } else if (madvise(reinterpret_cast<void*>(start), end - start, MADV_HUGEPAGE) != 0) {
        out.reason = "madvise(MADV_HUGEPAGE) failed: this kernel has no transparent huge pages";
    } else {
        out.advised = true;
        out.reservedBytes = end - start;
    }
    // Back to malloc: the block joins the free top; the trim threshold keeps it in the heap.
    std::free(block);
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
