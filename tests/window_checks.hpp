#pragma once
// What the window tests share besides their waits (window_waits.hpp): a folder of the
// test's own for the window's settings and recovery copies, and what the 3D view
// emphasises per link.
#include <algorithm>
#include <functional>
#include <memory>
#include <vector>

#include <QSettings>
#include <QTemporaryDir>

#include "ui/window/main_window.hpp"
#include "ui/window/scene_view.hpp"

namespace ll::test {

// Recovery copies, recent files and the remembered layout go to `dir`, not the user's.
inline void keepWindowStateIn(const QTemporaryDir& dir) {
    qputenv("LAGRANGELAB_RECOVERY_DIR", dir.filePath("recovery").toLocal8Bit());
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, dir.filePath("settings"));
}

// A window at 1280×800 on screen with `path` opened, once `ready` holds (a fatal test
// failure when it does not open).
inline std::unique_ptr<ui::MainWindow> openedWindow(const QString& path, const std::function<bool(ui::MainWindow&)>& ready) {
    auto w = std::make_unique<ui::MainWindow>();
    w->setAskBeforeClosing(false);
    w->resize(1280, 800);
    w->show();
    if (!w->openFile(path, nullptr, true) || !ready(*w)) qFatal("%s did not open", qPrintable(path));
    return w;
}

// Per link: the emphasis the 3D view draws on its rods and COM (−1 faded, 0..1 lit; the
// most of its parts), from the parts the view is told; −2 when nothing is emphasised.
inline std::vector<float> linkStrengths(ui::MainWindow& w) {
    const VisualScene& scene = *w.result()->visual;
    const VisualEmphasis& e = w.sceneView().emphasis();
    std::vector<float> out(static_cast<std::size_t>(scene.dof()), -2.0f);
    if (!e.active()) return out;
    for (std::size_t i = 0; i < scene.parts.size(); ++i) {
        const VisualPart& p = scene.parts[i];
        if (p.role != PartRole::Link && p.role != PartRole::CentreOfMass) continue;
        out[static_cast<std::size_t>(p.coordinate)] = std::max(out[static_cast<std::size_t>(p.coordinate)], e.strength[i]);
    }
    return out;
}

}  // namespace ll::test
