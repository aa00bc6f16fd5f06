#include "app/settled_screenshot.hpp"

#include "app/event_wait.hpp"
#include "ui/window/main_window.hpp"
#include "ui/window/scene_view.hpp"

namespace ll::cli {

QImage settledScreenshot(ui::MainWindow& window) {
    const long frames = window.sceneView().framesDrawn();
    window.sceneView().requestFrame();
    waitFor([&] { return window.sceneView().framesDrawn() > frames; }, 5);
    pauseFor(0.3);
    return window.screenshot();
}

}  // namespace ll::cli
