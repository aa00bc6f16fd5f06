// How a worker's result reaches the thread that owns it (ui/document/handover): every call
// posted from other threads runs exactly once, on the owner's thread, in the order each
// poster posted; a call may post again; calls never drained are dropped, not run, when the
// Handover goes. Labelled `threads`: under ThreadSanitizer, the payloads the workers wrote
// are read on the owner's thread, so a handover TSan cannot follow fails it.
#include "test_registry.hpp"

#include <QCoreApplication>
#include <QThread>
#include <memory>
#include <thread>
#include <vector>

#include "ui/document/handover.hpp"
#include "window_waits.hpp"

namespace test_handover {

using ll::ui::Handover;

class TestHandover : public QObject {
    Q_OBJECT

private slots:
    void everyCallRunsOnceOnTheOwnersThreadInOrder() {
        constexpr int posters = 3, calls = 400;
        Handover handover;
        std::vector<std::vector<int>> seen(posters);  // touched on this thread only
        int wrongThread = 0;
        std::vector<std::thread> threads;
        for (int p = 0; p < posters; ++p)
            threads.emplace_back([&, p] {
                for (int k = 0; k < calls; ++k) {
                    auto payload = std::make_shared<std::vector<int>>(std::vector<int>{p, k});  // written here, read there
                    handover.post([&, payload] {
                        if (QThread::currentThread() != QCoreApplication::instance()->thread()) ++wrongThread;
                        seen[std::size_t((*payload)[0])].push_back((*payload)[1]);
                    });
                }
            });
        for (auto& t : threads) t.join();
        QVERIFY(ll::test::waitUntil(
            [&] {
                std::size_t n = 0;
                for (const auto& s : seen) n += s.size();
                return n == std::size_t(posters * calls);
            },
            60000));
        QCoreApplication::processEvents();  // nothing more arrives
        QCOMPARE(wrongThread, 0);
        for (int p = 0; p < posters; ++p) {
            QCOMPARE(int(seen[std::size_t(p)].size()), calls);
            for (int k = 0; k < calls; ++k) QCOMPARE(seen[std::size_t(p)][std::size_t(k)], k);
        }
    }

    void aCallMayPostAgain() {
        Handover handover;
        std::vector<int> order;
        std::thread worker([&] {
            handover.post([&] {
                order.push_back(1);
                handover.post([&] { order.push_back(2); });
            });
        });
        worker.join();
        QVERIFY(ll::test::waitUntil([&] { return order.size() == 2; }, 60000));
        QCOMPARE(order, (std::vector<int>{1, 2}));
    }

    void undrainedCallsAreDroppedWithIt() {
        auto alive = std::make_shared<int>(0);
        int ran = 0;
        {
            Handover handover;
            std::thread worker([&] {
                for (int k = 0; k < 10; ++k) handover.post([&ran, alive] { ++ran; });
            });
            worker.join();
            QCOMPARE(alive.use_count(), 11L);  // held, waiting for this thread's event loop
        }
        QCoreApplication::processEvents();
        QCOMPARE(ran, 0);
        QCOMPARE(alive.use_count(), 1L);  // the captures were destroyed, not leaked
    }
};

LL_TEST_GUILESS_MAIN(TestHandover)

}  // namespace test_handover
#include "test_handover.moc"
