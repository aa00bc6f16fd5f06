// `bench --derive --chains A..B [SCENE...] [--batches N] [--cap S]`: the structured
// derivation (B, C, g over named quantities) on seeded random spatial chains of A to B
// joints, beside the expanded one (stopped past the time cap), with output sizes and
// how soon a cancelled structured derivation stops.
#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <numbers>
#include <random>
#include <thread>

#include <pthread.h>
#include <time.h>

#include "app/bench/bench.hpp"
#include "app/bench/bench_timing.hpp"
#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "app/scene_loading.hpp"
#include "core/model/cancellation.hpp"
#include "core/present/derivation_document.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/robot_derivation.hpp"
#include "core/present/structured_document.hpp"
#include "core/symbolic/structured_dynamics.hpp"

namespace ll::bench {

using namespace ll::cli;
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) { return std::chrono::duration<double, std::milli>(Clock::now() - start).count(); }

double threadCpuMs(clockid_t clock) {
    timespec ts{};
    clock_gettime(clock, &ts);
    return 1e3 * double(ts.tv_sec) + 1e-6 * double(ts.tv_nsec);
}

struct Latency {
    double wall = 0, cpu = 0;  // ms
};

// How soon the structured derivation stops after its flag is set at 1/4, 1/2, 3/4 of
// its uncancelled time: the largest latency [ms], as wall time and as the CPU time the
// derivation's thread spent after the flag was set (on a loaded machine the wall time
// is mostly waiting for a core).
Latency cancelLatency(const Scene& scene, double fullMs) {
    Latency worst;
    for (int k = 1; k < 4; ++k) {
        std::atomic<bool> cancel{false};
        Clock::time_point stopped;
        double stoppedCpu = 0;
        std::thread worker([&] {
            symbolic::DerivationOptions o;
            o.mode = symbolic::ParameterMode::Numeric;
            o.cancel = &cancel;
            try {
                (void)symbolic::deriveStructured(scene, o);
            } catch (const Cancelled&) {
            }
            stopped = Clock::now();
            stoppedCpu = threadCpuMs(CLOCK_THREAD_CPUTIME_ID);
        });
        clockid_t workerClock{};
        pthread_getcpuclockid(worker.native_handle(), &workerClock);
        std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(fullMs * k / 4));
        const auto set = Clock::now();
        const double setCpu = threadCpuMs(workerClock);
        cancel = true;
        worker.join();
        worst.wall = std::max(worst.wall, std::max(0.0, std::chrono::duration<double, std::milli>(stopped - set).count()));
        worst.cpu = std::max(worst.cpu, std::max(0.0, stoppedCpu - setCpu));
    }
    return worst;
}

// Returns whether the expanded derivation finished within the cap (not tried: false).
bool benchOne(const Scene& scene, const std::string& label, int repeats, double capSeconds, bool tryExpanded) {
    using namespace symbolic;
    using namespace present;
    DerivationOptions options;
    options.mode = ParameterMode::Numeric;
    std::vector<double> ms, cpu;
    int definitions = 0;
    std::size_t structuredKB = 0;
    for (int r = 0; r < repeats; ++r) {
        const auto start = Clock::now();
        const std::clock_t cpuStart = std::clock();
        const StructuredDynamics s = deriveStructured(scene, options);
        ms.push_back(msSince(start));
        cpu.push_back(1e3 * double(std::clock() - cpuStart) / CLOCKS_PER_SEC);
        if (r == 0) {
            const auto lock = lockGinac();
            definitions = s.table->size();
            StructuredDocumentInfo info;
            info.modeName = "numeric";
            info.formReason = literal("bench");
            structuredKB = structuredDocument(s, DocumentFormat::Json, info).size() / 1024;
        }
    }
    const double structured = median(ms);
    const Latency latency = cancelLatency(scene, structured);

    // The expanded derivation once, on a worker, cancelled at the cap.
    std::atomic<bool> cancel{false};
    double expandedMs = -1;
    std::size_t expandedKB = 0;
    std::thread worker([&] {
        if (!tryExpanded) return;
        DerivationOptions o = options;
        o.cancel = &cancel;
        const auto start = Clock::now();
        try {
            const auto lock = lockGinac();
            const Derivation d = deriveRobot(scene, o);
            expandedMs = msSince(start);
            expandedKB = derivationDocument(d, DocumentFormat::Json, "numeric").size() / 1024;
        } catch (const Cancelled&) {
        }
    });
    const auto start = Clock::now();
    while (tryExpanded && expandedMs < 0 && msSince(start) < 1e3 * capSeconds) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    cancel = true;
    worker.join();
    char expanded[64];
    if (!tryExpanded) std::snprintf(expanded, sizeof expanded, "skipped");
    else if (expandedMs < 0) std::snprintf(expanded, sizeof expanded, "> %.0f s (stopped)", capSeconds);
    else std::snprintf(expanded, sizeof expanded, "%.1f", expandedMs);
    char expandedSize[32];
    if (expandedMs < 0) std::snprintf(expandedSize, sizeof expandedSize, "-");
    else std::snprintf(expandedSize, sizeof expandedSize, "%zu", expandedKB);
    std::printf("%-22.22s %2d | %6d %11.2f %9.2f %9zu %10.2f %9.2f | %19s %10s\n", label.c_str(), scene.robot.dof(), definitions,
                structured, median(cpu), structuredKB, latency.wall, latency.cpu, expanded, expandedSize);
    std::fflush(stdout);
    return expandedMs >= 0;
}

// Seeded random spatial chains as the notes measured them: a, d ≠ 0, α ∈ {0, ±π/2},
// COM off-axis, diagonal inertia, gravity along −z.
Scene randomSpatialChain(int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> length(0.1, 0.5), mass(0.5, 5.0), com(-0.1, 0.1), inertia(0.01, 0.1);
    const double twists[] = {0.0, std::numbers::pi / 2, -std::numbers::pi / 2};
    Scene scene;
    scene.name = "random chain " + std::to_string(n) + " (seed " + std::to_string(seed) + ")";
    scene.robot.name = scene.name;
    scene.robot.joints.resize(n);
    for (int i = 0; i < n; ++i) {
        Joint& j = scene.robot.joints[i];
        j.dh.a = length(rng);
        j.dh.d = length(rng);
        j.dh.alpha = twists[rng() % 3];
        j.link.mass = mass(rng);
        j.link.com = {com(rng), com(rng), com(rng)};
        j.link.inertia.setZero();
        j.link.inertia.diagonal() << inertia(rng), inertia(rng), inertia(rng);
    }
    scene.effects.gravity = Eigen::Vector3d(0, 0, -9.81);
    return scene;
}

}  // namespace

int deriveChains(const std::string& range, const std::vector<std::string>& scenes, int repeats, double capSeconds) {
    const std::size_t dots = range.find("..");
    int first = 0, last = 0;
    try {
        first = std::stoi(range.substr(0, dots));
        last = dots == std::string::npos ? first : std::stoi(range.substr(dots + 2));
    } catch (const std::exception&) {
        throw UsageError("--chains: expected a joint count or a range such as 3..12, got '" + range + "'");
    }
    if (first < 1 || last > 60 || first > last)
        throw UsageError("--chains: joint counts run from 1 to 60, low to high, got '" + range + "'");
    std::printf("structured derivation of B, C, g (numeric mode, median of %d runs; wall and process CPU time)\n"
                "beside the expanded one\n"
                "(one run, stopped at %.0f s); sizes of the JSON documents; cancel: largest latency [ms] from\n"
                "setting the flag (at 1/4, 1/2, 3/4 of the run) to the structured derivation stopping, wall and\n"
                "the CPU time its thread spent meanwhile\n\n",
                repeats, capSeconds);
    std::printf("%-22s %2s | %6s %11s %9s %9s %10s %9s | %19s %10s\n", "system", "n", "names", "struct [ms]", "cpu [ms]", "JSON [KB]",
                "cancel [ms]", "cpu [ms]", "expanded [ms]", "JSON [KB]");
    for (const std::string& path : scenes) {
        const Scene scene = loadSceneReportingWarnings(path);
        if (!scene.lagrangian) benchOne(scene, scene.name, repeats, capSeconds, true);
    }
    // Once a chain's expanded derivation passed the cap, longer chains are not tried (its
    // cancel checkpoints sit between entries that take minutes to reduce at 8+ joints).
    bool tryExpanded = true;
    for (int n = first; n <= last; ++n)
        tryExpanded = benchOne(randomSpatialChain(n, 1000 + n), "random chain", repeats, capSeconds, tryExpanded);
    std::printf("\nskipped: the expanded derivation of a shorter chain already passed the cap.\n");
    return 0;
}

}  // namespace ll::bench
