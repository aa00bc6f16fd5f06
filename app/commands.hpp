#pragma once
// The `lagrangelab <command>` entry points. Each returns the process exit code:
// 0 success, 2 bad input (scene or command line), 3 the simulation stopped early.
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ll {
struct WorkPrecisionResult;
namespace symbolic {
struct DisplayDocument;
}  // namespace symbolic
}  // namespace ll

namespace ll::cli {

using Args = std::vector<std::string>;

int evalCommand(const Args& args);
int simulateCommand(const Args& args);
int integratorsCommand(const Args& args);
int benchCommand(const Args& args);
int accuracyCommand(const Args& args);
int deriveCommand(const Args& args);
int renderCommand(const Args& args);
int codegenCommand(const Args& args);
// `bench --derive --chains A..B`: structured beside expanded on random chains (app/bench_derive_chains.cpp).
int benchDeriveChains(const std::string& range, const std::vector<std::string>& scenes, int repeats, double capSeconds);
// `bench --render`: the cost of headless export (app/bench_render.cpp).
int benchRender(const std::vector<std::string>& scenes, int runs);
// `bench --typeset`: typesetting and printing the derivation (app/bench_typeset.cpp).
int benchTypeset(const std::vector<std::string>& scenes, int runs);
// `bench --process`: whole derive processes against the derivation inside (app/bench_process.cpp).
int benchProcess(const std::vector<std::string>& scenes, int runs, const std::string& form);
// Whether `lagrangelab COMMAND ARGS…` paints (Qt, OpenSceneGraph): the window, render,
// derive --format pdf|svg|png, accuracy --out, bench --gui|--render|--typeset. Those run in
// lagrangelab-gui; the rest run in lagrangelab, which loads neither (app/graphics_handoff.hpp).
bool commandPaints(const std::string& command, const Args& args);

// The painting parts, defined in lagrangelab-gui (in lagrangelab they hand the command
// line over to it).
// derive --format pdf|svg|png: the typeset pages of a display document (app/derive_pages.cpp).
int writeDerivationPages(const symbolic::DisplayDocument& display, const std::string& format, const std::string& outPath,
                         bool timings);
// accuracy --out: the work–precision plot, .svg or .png (app/accuracy_plot.cpp).
void saveAccuracyPlot(const WorkPrecisionResult& result, const std::string& path);
// The desktop window: `lagrangelab [SCENE] [--screenshot FILE.png …]` (app/window_command.cpp).
int windowCommand(const Args& args, const std::chrono::steady_clock::time_point& processStart);
// `bench --gui`: edit-to-view latency, animation frame rate, start to first frame (app/bench_gui.cpp).
int benchGui(const std::vector<std::string>& scenes, int runs);

}  // namespace ll::cli
