#include "app/bench/window_bench.hpp"

#include <cstdio>

#include <QFile>

#include "app/offscreen_gui.hpp"

namespace ll::bench {

std::unique_ptr<QApplication> windowBenchApplication(const char* mode, const QTemporaryDir& recovery) {
    if (!cli::hasDisplay()) {
        std::fprintf(stderr, "error: bench --%s: no display (run it under xvfb-run -a -s '-screen 0 1280x800x24')\n", mode);
        return nullptr;
    }
    cli::providePrivateRuntimeDirectory();
    if (recovery.isValid()) qputenv("LAGRANGELAB_RECOVERY_DIR", recovery.path().toLocal8Bit());
    static int argc = 1;
    static char name[] = "lagrangelab";
    static char* argv[] = {name, nullptr};
    auto app = std::make_unique<QApplication>(argc, argv);
    QFile loadavg("/proc/loadavg");
    if (loadavg.open(QIODevice::ReadOnly)) std::printf("load average at start: %s", loadavg.readLine().constData());
    return app;
}

}  // namespace ll::bench
