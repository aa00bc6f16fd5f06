#include "app/settled_screenshot.hpp"

#include "app/event_wait.hpp"
#include "ui/window/main_window.hpp"
#include "ui/window/scene_view.hpp"

namespace ll::cli {

QImage settledScreenshot(ui::MainWindow& window) {
    const long frames = window.sceneView().framesDrawn();
    window.sceneView().requestFrame();
    waitFor([&] { return window.sceneView().framesDrawn() > frames; }, 5);
    // The plots repaint the regions they changed a little later (Qt Charts lays its axes
    // out in passes): grabbed until two grabs 50 ms apart are the same picture.
    QImage last = window.screenshot();
    for (int k = 0; k < 40; ++k) {
        pauseFor(0.05);
        QImage now = window.screenshot();
        if (now == last) return now;
        last = std::move(now);
    }
    return last;
}

}  // namespace ll::cli
