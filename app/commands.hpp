#pragma once
// The `lagrangelab <command>` entry points. Each returns the process exit code:
// 0 success, 2 bad input (scene or command line), 3 the simulation stopped early.
#include <chrono>
#include <string>
#include <vector>

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
// The desktop window: `lagrangelab [SCENE] [--screenshot FILE.png …]` (app/window_command.cpp).
int windowCommand(const Args& args, const std::chrono::steady_clock::time_point& processStart);
// `bench --gui`: edit-to-view latency, animation frame rate, start to first frame (app/bench_gui.cpp).
int benchGui(const std::vector<std::string>& scenes, int runs);
bool hasDisplay();

}  // namespace ll::cli
