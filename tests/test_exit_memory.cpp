// exit_memory: dispose() frees at once until the process says it leaves its memory to
// its exit; after that it keeps what it is given alive (never destroyed), from any thread.
#include <QtTest>

#include <atomic>
#include <thread>
#include <vector>

#include "core/model/exit_memory.hpp"

using namespace ll;

namespace {

std::atomic<int> freedCount{0};

std::shared_ptr<const void> counted() {
    return std::shared_ptr<const int>(new int(7), [](const int* p) {
        delete p;
        ++freedCount;
    });
}

// Counts its destructions, to watch Disposing and disposeValue.
struct Tracked {
    int value;
    explicit Tracked(int v) : value(v) {}
    Tracked(Tracked&& o) noexcept : value(o.value) { o.value = -1; }
    ~Tracked() {
        if (value >= 0) ++freedCount;  // a moved-from shell is not counted
    }
};

}  // namespace

class TestExitMemory : public QObject {
    Q_OBJECT

private slots:
    void freedAtOnceUntilLeft() {
        QVERIFY(!memoryLeftToExit());
        freedCount = 0;
        dispose(counted());
        QCOMPARE(freedCount.load(), 1);
        auto shared = counted();
        auto other = shared;
        dispose(std::move(shared));
        QCOMPARE(freedCount.load(), 1);  // another owner: still alive
        other.reset();
        QCOMPARE(freedCount.load(), 2);
        dispose(nullptr);  // nothing to do
    }

    void disposingFreesAtItsEndUntilLeft() {
        QVERIFY(!memoryLeftToExit());
        freedCount = 0;
        {
            const Disposing<Tracked> owned(3);
            QCOMPARE(owned->value, 3);
            QCOMPARE((*owned).value, 3);
            QCOMPARE(freedCount.load(), 0);
        }
        QCOMPARE(freedCount.load(), 1);
        {
            Disposing<Tracked> owned(4);
            owned.disposeNow();
            QCOMPARE(freedCount.load(), 2);  // at once, not at the end
        }
        QCOMPARE(freedCount.load(), 2);  // and not twice
        try {
            const Disposing<Tracked> owned(5);
            throw 1;
        } catch (int) {
        }
        QCOMPARE(freedCount.load(), 3);  // also when an exception passes
        Tracked local(6);
        disposeValue(std::move(local));
        QCOMPARE(freedCount.load(), 4);
        QCOMPARE(local.value, -1);  // moved into the owner that was freed
    }

    void keptOnceLeft() {
        leaveMemoryToExit();
        QVERIFY(memoryLeftToExit());
        freedCount = 0;
        std::weak_ptr<const void> watch;
        {
            auto object = counted();
            watch = object;
            dispose(std::move(object));
        }
        QVERIFY(!watch.expired());
        std::vector<std::thread> threads;
        for (int t = 0; t < 4; ++t)
            threads.emplace_back([] {
                for (int i = 0; i < 1000; ++i) dispose(counted());
            });
        for (std::thread& t : threads) t.join();
        {
            const Disposing<Tracked> owned(8);
            Disposing<Tracked> early(9);
            early.disposeNow();
        }
        disposeValue(Tracked(10));
        QCOMPARE(freedCount.load(), 0);
    }
};

QTEST_GUILESS_MAIN(TestExitMemory)
#include "test_exit_memory.moc"
