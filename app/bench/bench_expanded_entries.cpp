// lagrangelab-bench --entries: one entry of B and of C expanded on demand from the
// structured form (what `derive --form expanded --entry B11` does), on a chain whose
// constant angles are special (multiples of π/2, θ = 0) beside the same chain with
// general ones (twists 0.3 rad, θ = 0.624 rad), whose sines and cosines are folded to
// numbers (issue 39). Each run derives afresh: the table memoises what it unfolded.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "app/bench/bench.hpp"
#include "app/bench/bench_timing.hpp"
#include "app/scene_loading.hpp"
#include "core/io/data_directory.hpp"
#include "core/symbolic/structured_dynamics.hpp"
#include "core/symbolic/structured_entries.hpp"

namespace ll::bench {

int expandedEntries(const std::vector<std::string>& scenes, const std::vector<std::string>& entries, int runs) {
    using Clock = std::chrono::steady_clock;
    std::printf("median over %d runs [s]: the structured form derived, then the entry expanded from its names\n\n", runs);
    std::printf("%-36s %-6s %9s %9s %9s\n", "scene", "entry", "terms", "derive", "expand");
    for (const std::string& path : scenes) {
        const Scene scene = cli::loadSceneReportingWarnings(path);
        for (const std::string& name : entries) {
            std::vector<double> derive, expand;
            std::size_t terms = 0;
            for (int r = 0; r < runs; ++r) {
                const auto t0 = Clock::now();
                symbolic::StructuredDynamics s = symbolic::deriveStructured(scene);
                const auto t1 = Clock::now();
                terms = symbolic::expandEntry(s, symbolic::parseEntry(name, s.n)).terms;
                const auto t2 = Clock::now();
                derive.push_back(std::chrono::duration<double>(t1 - t0).count());
                expand.push_back(std::chrono::duration<double>(t2 - t1).count());
            }
            std::printf("%-36.36s %-6s %9zu %9.3f %9.3f\n", scene.name.c_str(), name.c_str(), terms, cli::median(derive),
                        cli::median(expand));
        }
    }
    return 0;
}

// The default scenes: docs/bench/ beside the examples of the source tree.
std::vector<std::string> benchChains() {
    const std::filesystem::path bench = std::filesystem::canonical(examplesDirectory()).parent_path() / "docs" / "bench";
    std::vector<std::string> scenes;
    for (const char* name : {"chain8.json", "chain8_special.json", "chain8_general.json"}) scenes.push_back((bench / name).string());
    return scenes;
}

}  // namespace ll::bench
