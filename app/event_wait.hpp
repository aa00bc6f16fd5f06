#pragma once
// Waiting in a GUI command (the scripted window, bench --gui) while the event loop runs:
// workers deliver their results through queued calls, so a wait must keep processing.
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

namespace ll::cli {

// Processes events until done() or `seconds` pass; false on timeout. The thread sleeps
// between events (a 5 ms timer wakes it to look at done() again): a loop that polled
// without waiting kept one of the machine's two cores busy, which the workers and
// llvmpipe's threads being measured then did not get (bench --gui's latencies, frame
// rate and CPU times counted that spinning).
template <class F>
bool waitFor(F&& done, double seconds) {
    QElapsedTimer clock;
    clock.start();
    QTimer wake;
    wake.start(5);
    while (!done()) {
        if (clock.elapsed() > seconds * 1000) return false;
        QCoreApplication::processEvents(QEventLoop::AllEvents | QEventLoop::WaitForMoreEvents);
    }
    return true;
}

// Processes events for `seconds`.
inline void pauseFor(double seconds) {
    waitFor([] { return false; }, seconds);
}

}  // namespace ll::cli
