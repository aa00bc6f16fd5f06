#pragma once
// A QGuiApplication for commands that paint text headless (accuracy --out, render):
// fonts need one. With no display it runs on Qt's offscreen platform.
#include <cstdlib>
#include <memory>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

#include <QGuiApplication>

namespace ll::cli {

// An X or Wayland display to open a window on.
inline bool hasDisplay() { return std::getenv("DISPLAY") != nullptr || std::getenv("WAYLAND_DISPLAY") != nullptr; }

// Qt wants a runtime folder (XDG_RUNTIME_DIR) and says so on stderr when a session has
// none (ssh, containers, CI): "QStandardPaths: XDG_RUNTIME_DIR not set". Give it a
// private one, /tmp/lagrangelab-runtime-UID with mode 0700, owned by us and not a link;
// when that cannot be had, Qt's own message stays (it names a real problem then).
inline void providePrivateRuntimeDirectory() {
    if (std::getenv("XDG_RUNTIME_DIR") != nullptr) return;
    const std::string dir = "/tmp/lagrangelab-runtime-" + std::to_string(::getuid());
    ::mkdir(dir.c_str(), 0700);
    struct stat st {};
    if (::lstat(dir.c_str(), &st) == 0 && S_ISDIR(st.st_mode) && st.st_uid == ::getuid() && (st.st_mode & 0777) == 0700)
        setenv("XDG_RUNTIME_DIR", dir.c_str(), 1);
}

// A new application, or null when one exists already.
inline std::unique_ptr<QGuiApplication> makeGuiApplication() {
    if (QGuiApplication::instance()) return nullptr;
    providePrivateRuntimeDirectory();
    if (std::getenv("DISPLAY") == nullptr && std::getenv("WAYLAND_DISPLAY") == nullptr && std::getenv("QT_QPA_PLATFORM") == nullptr)
        setenv("QT_QPA_PLATFORM", "offscreen", 1);
    static int argc = 1;
    static char name[] = "lagrangelab";
    static char* argv[] = {name, nullptr};
    return std::make_unique<QGuiApplication>(argc, argv);
}

}  // namespace ll::cli
