#pragma once
// What the window tests wait for: conditions the window reaches (a result shown, an edit
// checked, a frame drawn), never a fixed time. Each wait processes events until its
// condition holds; its limit only makes a broken build fail instead of hang, and a loaded
// machine only makes it take longer.
#include <functional>

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QtTest>

#include "ui/window/main_window.hpp"
#include "ui/window/scene_view.hpp"

namespace ll::test {

// Processes events until `done` holds (true) or `milliseconds` pass (false). Unlike
// QTest::qWaitFor, which sleeps 10 ms between its checks without processing events,
// this checks after every millisecond of event processing: the 10,000-edit fuzz waits
// twice per edit, and 10 ms sleeps made it several minutes longer.
inline bool waitUntil(const std::function<bool()>& done, int milliseconds) {
    const QDeadlineTimer deadline(milliseconds);
    while (!done()) {
        if (deadline.hasExpired()) return false;
        QTest::qWait(1);
    }
    return true;
}

// The window shows a simulation of its newest valid scene, and no derivation is running.
inline bool settled(ui::MainWindow& w, int seconds = 60) {
    return waitUntil(
        [&] {
            return w.result() && !w.liveSimulation().busy() && !w.liveDerivation().busy() &&
                   w.result()->request == w.liveSimulation().latestRequest();
        },
        seconds * 1000);
}

// The newest edit has been checked (diagnostics and the valid scene up to date).
inline bool checked(ui::MainWindow& w, int seconds = 30) {
    return waitUntil([&] { return !w.document().validating(); }, seconds * 1000);
}

// Every event posted so far delivered, and those they post in turn (layout requests,
// 0 ms single-shot timers, repaints): what the window does next without time passing.
inline void flushEvents() {
    for (int i = 0; i < 4; ++i) {
        QCoreApplication::sendPostedEvents();
        QCoreApplication::processEvents(QEventLoop::AllEvents);
    }
}

// Nothing left to do: the edit checked, its simulation shown, no derivation running, and
// nothing posted that would start one.
inline bool idle(ui::MainWindow& w) {
    flushEvents();
    if (!checked(w) || !settled(w)) return false;
    flushEvents();
    return !w.document().validating() && !w.liveSimulation().busy() && !w.liveDerivation().busy();
}

// The 3D view has drawn a frame after everything posted before this call.
inline bool nextFrameDrawn(ui::MainWindow& w, int seconds = 10) {
    flushEvents();
    const long frames = w.sceneView().framesDrawn();
    w.sceneView().requestFrame();
    return waitUntil([&] { return w.sceneView().framesDrawn() > frames; }, seconds * 1000);
}

}  // namespace ll::test
