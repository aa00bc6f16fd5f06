#pragma once
// A QGuiApplication for commands that paint text headless (accuracy --out, render):
// fonts need one. With no display it runs on Qt's offscreen platform.
#include <cstdlib>
#include <memory>

#include <QGuiApplication>

namespace ll::cli {

// A new application, or null when one exists already.
inline std::unique_ptr<QGuiApplication> makeGuiApplication() {
    if (QGuiApplication::instance()) return nullptr;
    if (std::getenv("DISPLAY") == nullptr && std::getenv("WAYLAND_DISPLAY") == nullptr && std::getenv("QT_QPA_PLATFORM") == nullptr)
        setenv("QT_QPA_PLATFORM", "offscreen", 1);
    static int argc = 1;
    static char name[] = "lagrangelab";
    static char* argv[] = {name, nullptr};
    return std::make_unique<QGuiApplication>(argc, argv);
}

}  // namespace ll::cli
