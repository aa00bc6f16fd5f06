#pragma once
// What the benchmarks of the window (--gui, --lesson) share: the application they run in.
#include <memory>

#include <QApplication>
#include <QTemporaryDir>

namespace ll::bench {

// A QApplication for timing windows, or null (with an error line naming `mode`) without a
// display. The windows' autosaves go to `recovery`, not the user's recovery copy (which
// the next start would offer), and the load average at start is printed: wall times
// depend on what else the machine runs.
std::unique_ptr<QApplication> windowBenchApplication(const char* mode, const QTemporaryDir& recovery);

}  // namespace ll::bench
