#pragma once
// Waiting in a GUI command (the scripted window, bench --gui) while the event loop runs:
// workers deliver their results through queued calls, so a wait must keep processing.
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>

namespace ll::cli {

// Processes events until done() or `seconds` pass; false on timeout.
template <class F>
bool waitFor(F&& done, double seconds) {
    QElapsedTimer clock;
    clock.start();
    while (!done()) {
        if (clock.elapsed() > seconds * 1000) return false;
        QCoreApplication::processEvents(QEventLoop::AllEvents, 1);
    }
    return true;
}

// Processes events for `seconds`.
inline void pauseFor(double seconds) {
    waitFor([] { return false; }, seconds);
}

}  // namespace ll::cli
