// huge_page_heap: after useHugePagesForHeap, what the main thread allocates (small
// objects and strings of megabytes alike) lies in a mapping advised for huge pages
// (/proc/self/smaps: VmFlags "hg"), touching it is served by 2 MiB pages (AnonHugePages),
// and reserving the range used no memory. On a kernel with THP off it says so instead.
#include <QtTest>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/io/huge_page_heap.hpp"

using namespace ll;

namespace {

struct Mapping {
    bool found = false;
    bool hugeAdvised = false;   // VmFlags has "hg"
    long anonHugeKb = 0;        // AnonHugePages
};

Mapping mappingOf(const void* address) {
    const auto a = reinterpret_cast<std::uintptr_t>(address);
    std::ifstream smaps("/proc/self/smaps");
    Mapping m;
    bool inside = false;
    for (std::string line; std::getline(smaps, line);) {
        std::uintptr_t start = 0, end = 0;
        char dash = 0;
        std::istringstream head(line);
        if (line.find(':') > line.find(' ') && (head >> std::hex >> start >> dash >> end) && dash == '-') {
            if (inside) break;  // past the mapping
            inside = a >= start && a < end;
            m.found = inside;
            continue;
        }
        if (!inside) continue;
        if (line.rfind("AnonHugePages:", 0) == 0) m.anonHugeKb = std::stol(line.substr(14));
        if (line.rfind("VmFlags:", 0) == 0) m.hugeAdvised = (line + " ").find(" hg ") != std::string::npos;
    }
    return m;
}

long residentKb() {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
    return -1;
}

bool thpOff() {
    std::ifstream enabled("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string text;
    std::getline(enabled, text);
    return text.empty() || text.find("[never]") != std::string::npos;
}

}  // namespace

class TestHugePageHeap : public QObject {
    Q_OBJECT

private slots:
    void laterAllocationsLieInAnAdvisedRange() {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
        QSKIP("a sanitizer's allocator replaces glibc's malloc: mallopt and the heap are not its");
#endif
        const long rssBefore = residentKb();
        const HugePageHeap heap = useHugePagesForHeap();  // as `derive` calls it: 1 GiB
        if (thpOff()) {
            QVERIFY(!heap.advised);
            QVERIFY(std::strlen(heap.reason) > 0);
            QSKIP("transparent huge pages are off on this kernel: nothing to advise");
        }
        QVERIFY2(heap.advised, heap.reason);
        const HugePageHeap again = useHugePagesForHeap();  // once per process: the same range
        QVERIFY(again.advised);
        QCOMPARE(again.reservedBytes, heap.reservedBytes);
        QVERIFY(heap.reservedBytes >= (std::size_t(1020) << 20));
        // 1 GiB of address space, none of it touched.
        QVERIFY2(residentKb() - rssBefore < 16 * 1024, qPrintable(QString::number(residentKb() - rssBefore)));

        // Small objects: the first 2 MiB may fill the heap's head, below the first 2 MiB
        // boundary (no huge page fits there); the rest come from the advised range.
        std::vector<void*> small;
        for (int i = 0; i < 40000; ++i) small.push_back(std::malloc(48 + i % 200));
        for (void* p : {small[30000], small[35000], small.back()}) {
            const Mapping m = mappingOf(p);
            QVERIFY(m.found);
            QVERIFY(m.hugeAdvised);
        }
        // A document string of 20 MiB: from the heap (below the 32 MiB threshold), advised.
        std::string document(std::size_t(20) << 20, 'x');
        const Mapping big = mappingOf(document.data());
        QVERIFY(big.found);
        QVERIFY(big.hugeAdvised);
        // Touched (filled above), it is served by huge pages, not by 5,000 small ones.
        const long hugeKb = mappingOf(document.data()).anonHugeKb;
        QVERIFY2(hugeKb >= 2048, qPrintable(QString("AnonHugePages %1 kB").arg(hugeKb)));
        // Still advised, and still there, after megabytes are freed and allocated again
        // (a trim would give the range back to the system, advice and all).
        std::string().swap(document);
        std::vector<std::string> later;
        for (int i = 0; i < 64; ++i) later.emplace_back(std::size_t(1) << 20, 'y');
        for (const std::string& s : later) QVERIFY(mappingOf(s.data()).hugeAdvised);
        for (void* p : small) std::free(p);
    }
};

QTEST_GUILESS_MAIN(TestHugePageHeap)
#include "test_huge_page_heap.moc"
