// lagrangelab-bench --process [SCENE...] [--batches N] [--form auto|structured|expanded]:
// whole `lagrangelab derive` processes as a user starts them, in every format, against
// the budgets of docs/benchmarks.md: every example and format ≤ 0.5 s, the PUMA 560's
// JSON ≤ 0.3 s. Each run is timed from just before posix_spawn to just after waitpid;
// the formats take turns within each round, so a slow spell of the machine is shared.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include "app/bench/bench.hpp"
#include "app/bench/bench_timing.hpp"
#include "app/bench/program_run.hpp"
#include "core/io/data_directory.hpp"

namespace ll::bench {

using ll::cli::median;

namespace {

namespace fs = std::filesystem;

const char* const formats[] = {"text", "latex", "json", "pdf", "svg", "png"};
constexpr int formatCount = sizeof formats / sizeof *formats;

// The budget of one process, in seconds.
double budgetOf(const fs::path& scene, const std::string& format) {
    if (scene.filename() == "puma560.json" && format == "json") return 0.3;
    return 0.5;
}

}  // namespace

int process(const std::vector<std::string>& scenesGiven, int runs, const std::string& form) {
    std::vector<fs::path> scenes(scenesGiven.begin(), scenesGiven.end());
    if (scenes.empty()) {
        for (const fs::directory_entry& e : fs::directory_iterator(examplesDirectory()))
            if (e.path().extension() == ".json") scenes.push_back(e.path());
        std::sort(scenes.begin(), scenes.end());
    }
    const fs::path dir = fs::temp_directory_path() / ("lagrangelab-bench-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path log = dir / "derive.log";

    std::printf("whole `lagrangelab derive SCENE --format F --form %s` processes (spawn to reap), median [s] of %d\n"
                "runs; the formats take turns within each round; pdf, svg and png written with --out\n\n",
                form.c_str(), runs);
    std::printf("%-28s", "scene");
    for (const char* f : formats) std::printf(" %7s", f);
    std::printf("  budget\n");
    int over = 0, failed = 0;
    for (const fs::path& scene : scenes) {
        std::vector<double> seconds[formatCount];
        int exitCode[formatCount] = {};
        for (int r = 0; r < runs; ++r)
            for (int f = 0; f < formatCount; ++f) {
                std::vector<std::string> args = {"derive", scene.string(), "--format", formats[f], "--form", form};
                if (f >= 3) args.insert(args.end(), {"--out", (dir / (std::string("page.") + formats[f])).string()});
                const auto start = std::chrono::steady_clock::now();
                const int code = runLagrangelab(args, log);
                seconds[f].push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
                if (code != 0) exitCode[f] = code;
            }
        std::printf("%-28.28s", scene.stem().c_str());
        std::string verdict = "ok";
        for (int f = 0; f < formatCount; ++f) {
            if (exitCode[f] != 0) {
                std::printf(" %7s", ("exit" + std::to_string(exitCode[f])).c_str());
                ++failed;
                verdict = "FAILED";
                continue;
            }
            const double m = median(seconds[f]);
            const bool within = m <= budgetOf(scene, formats[f]);
            std::printf(" %6.3f%s", m, within ? " " : "!");
            if (!within) {
                ++over;
                if (verdict == "ok") verdict = "OVER";
            }
        }
        std::printf("  %s\n", verdict.c_str());
    }
    std::error_code ignored;
    fs::remove_all(dir, ignored);
    std::printf("\nbudgets: 0.5 s for every scene and format, 0.3 s for the PUMA 560's JSON; '!' marks a median over\n"
                "its budget (%d here); %d format%s failed.\n",
                over, failed, failed == 1 ? "" : "s");
    return failed ? 1 : 0;
}

}  // namespace ll::bench
