// lagrangelab-bench: the benchmarks (usage below). By default the median times of our
// dynamics on seeded random states (app/bench/bench_timing.hpp; KDL's solvers on the
// same states: tests/oracle/bench_kdl.cpp); with --rhs, one right-hand-side evaluation
// with no effects, gravity only and all effects; the other modes in their own files.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <thread>

#include "app/bench/bench.hpp"
#include "app/bench/bench_timing.hpp"
#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "core/model/diagnostics.hpp"
#include "app/scene_loading.hpp"
#include "core/dynamics/coriolis.hpp"
#include "core/dynamics/forward_dynamics.hpp"
#include "core/dynamics/potential_gradient.hpp"
#include "core/dynamics/inverse_dynamics.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/simulation/robot_ode.hpp"
#include "core/pipeline/scene_simulation.hpp"
#include "core/model/cancellation.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/lagrangian_derivation.hpp"
#include "core/symbolic/robot_derivation.hpp"
#include "core/io/data_directory.hpp"

namespace ll::bench {

using namespace ll::cli;
namespace {

// An installed example scene by name (bench's default scenes).
std::string example(const char* name) { return (examplesDirectory() / (std::string(name) + ".json")).string(); }

// `bench --rhs`: one right-hand-side evaluation (RobotOde, composed from the declared
// effects) with no effects, gravity only, and every effect, on the same states.
int benchRhs(const std::vector<std::string>& scenes, int batches) {
    std::printf("median time of one right-hand-side evaluation f(x, t) [µs] over %d batches of random states;\n"
                "the right-hand side is composed from the declared effects only\n\n",
                batches);
    std::printf("%-24s %2s | %10s %12s %12s %15s\n", "robot", "n", "no effects", "gravity only", "all effects", "gravity + CT");
    for (const std::string& path : scenes) {
        const Scene scene = loadSceneReportingWarnings(path);
        const RobotModel& robot = scene.robot;
        const int n = robot.dof();
        const States s = randomStates(robot, 64);
        Effects none, gravity, all, controlled;
        gravity.gravity = all.gravity = scene.effects.gravity.value_or(Eigen::Vector3d(0, 0, -9.81));
        // Computed torque following a quintic: one more Newton–Euler pass per call.
        controlled.gravity = gravity.gravity;
        Control ct;
        ct.law = ControlLaw::ComputedTorque;
        ct.kp = Eigen::VectorXd::Constant(n, 100.0);
        ct.kd = Eigen::VectorXd::Constant(n, 20.0);
        ct.reference.kind = ControlReference::Kind::Quintic;
        ct.reference.q0 = Eigen::VectorXd::Zero(n);
        ct.reference.q1 = Eigen::VectorXd::Constant(n, 0.5);
        ct.reference.duration = 10.0;
        controlled.control = ct;
        for (int j = 0; j < n; ++j) {
            all.springs.push_back({j, 10.0, 0.0});
            all.viscous.push_back({j, 0.1});
            all.coulomb.push_back({j, 0.2, 1e-3});
            JointTorque torque;
            torque.joint = j;
            torque.kind = TorqueKind::Sine;
            torque.amplitude = 1.0;
            torque.frequency = 0.5;
            all.torques.push_back(torque);
        }
        const auto time = [&](const Effects& effects) {
            RobotOde ode(robot, effects);
            std::vector<OdeState> xs;
            for (size_t k = 0; k < s.q.size(); ++k) xs.push_back(ode.initialState(s.q[k], s.qd[k]));
            OdeState dxdt(xs[0].size());
            return medianMicros(batches, static_cast<int>(xs.size()), [&](int k) { ode(xs[k], dxdt, 0.1 * k); });
        };
        std::printf("%-24.24s %2d | %10.3f %12.3f %12.3f %15.3f\n", scene.name.c_str(), n, time(none), time(gravity), time(all),
                    time(controlled));
    }
    std::printf("\nall effects: gravity, a spring, viscous and Coulomb friction and a sine torque on every joint.\n"
                "gravity + CT: gravity and a computed-torque controller (core/simulation/controller) following a quintic.\n");
    return 0;
}

// `bench --derive`: wall time of the whole symbolic derivation (steps 0–8, incl. C)
// per parameter mode, median of `repeats` runs.
int benchDerive(const std::vector<std::string>& scenes, int repeats) {
    using namespace ll::symbolic;
    std::printf("median wall time [ms] of the whole derivation (steps 0-8, incl. C) over %d runs\n\n", repeats);
    std::printf("%-30s %2s | %11s %11s %11s\n", "system", "n", "parameters", "numeric", "symbolic");
    for (const std::string& path : scenes) {
        const Scene scene = loadSceneReportingWarnings(path);
        std::printf("%-30.30s %2d |", scene.name.c_str(), scene.dof());
        for (ParameterMode mode : {ParameterMode::Parametric, ParameterMode::Numeric, ParameterMode::Textbook}) {
            std::vector<double> ms;
            for (int r = 0; r < repeats; ++r) {
                const auto start = std::chrono::steady_clock::now();
                DerivationOptions options;
                options.mode = mode;
                const Derivation d = scene.lagrangian ? deriveLagrangian(scene, mode) : deriveRobot(scene, options);
                ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
            }
            std::sort(ms.begin(), ms.end());
            std::printf(" %11.2f", ms[ms.size() / 2]);
        }
        std::printf("\n");
    }
    return 0;
}

// `bench --cancel`: how soon a derivation stops once its cancel flag is set (what a
// stale derivation costs the window after an edit). Each robot is derived fully
// symbolically on a worker; the flag is set at 1/8 … 7/8 of its uncancelled time.
int benchCancel(const std::vector<std::string>& scenes) {
    std::printf("latency [ms] from setting the cancel flag to the derivation stopping (fully symbolic;\n"
                "flag set at 1/8 ... 7/8 of the uncancelled derivation time)\n\n");
    std::printf("%-30s %2s | %12s | %8s %8s\n", "system", "n", "derive [ms]", "median", "max");
    for (const std::string& path : scenes) {
        const Scene scene = loadSceneReportingWarnings(path);
        if (scene.lagrangian) continue;
        symbolic::DerivationOptions options;
        options.mode = symbolic::ParameterMode::Textbook;
        const auto start = std::chrono::steady_clock::now();
        {
            const auto lock = symbolic::lockGinac();
            (void)symbolic::deriveRobot(scene, options);
        }
        const double full = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        std::vector<double> latency;
        for (int k = 1; k < 8; ++k) {
            std::atomic<bool> cancel{false};
            std::chrono::steady_clock::time_point stopped;
            std::thread worker([&] {
                symbolic::DerivationOptions o = options;
                o.cancel = &cancel;
                try {
                    const auto lock = symbolic::lockGinac();
                    (void)symbolic::deriveRobot(scene, o);
                } catch (const Cancelled&) {
                }
                stopped = std::chrono::steady_clock::now();
            });
            std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(full * k / 8));
            const auto set = std::chrono::steady_clock::now();
            cancel = true;
            worker.join();
            latency.push_back(std::max(0.0, std::chrono::duration<double, std::milli>(stopped - set).count()));
        }
        std::sort(latency.begin(), latency.end());
        std::printf("%-30.30s %2d | %12.1f | %8.2f %8.2f\n", scene.name.c_str(), scene.dof(), full, latency[latency.size() / 2],
                    latency.back());
    }
    return 0;
}

// The default table: B, C, g, forward and inverse dynamics, one simulated second.
int dynamics(std::vector<std::string> scenes, int batches) {
    if (scenes.empty())
        for (const char* name : {"puma560", "stanford_arm", "ur5", "panda", "planar_2r"}) scenes.push_back(example(name));

    std::printf("median time per call [µs] over %d batches of random states; 'sim 1 s' is CPU time [ms] for one\n"
                "simulated second with the scene's integrator and tolerances (median of 5)\n\n",
                batches);
    std::printf("%-24s %2s | %7s %7s %7s %7s %7s %9s", "robot", "n", "B", "C", "g", "FD", "RNEA", "sim 1 s");
    std::printf("\n");
    for (const std::string& path : scenes) {
        const Scene scene = loadSceneReportingWarnings(path);
        const RobotModel& robot = scene.robot;
        const Effects& effects = scene.effects;
        const int n = robot.dof();
        const States s = randomStates(robot, 64);
        const DynamicsTimes t = dynamicsTimes(robot, effects, s, batches);
        std::vector<double> simMs;
        SimulationSettings oneSecond = scene.simulation;
        oneSecond.duration = 1.0;
        for (int r = 0; r < 5; ++r) simMs.push_back(1e3 * simulate(scene, oneSecond).stats.cpuSeconds);
        std::sort(simMs.begin(), simMs.end());

        std::printf("%-24.24s %2d | %7.3f %7.3f %7.3f %7.3f %7.3f %9.3f", scene.name.c_str(), n, t.B, t.C, t.g, t.FD, t.RNEA, simMs[2]);
        std::printf("\n");
    }
    std::printf("\nB: kinematics + CRBA; C: + Christoffel matrix; FD: q̈ = B⁻¹(Q − C q̇ − g); RNEA: inverse dynamics.\n"
                "KDL's solvers on the same states: build/tests/lagrangelab_bench_kdl in a build tree with\n"
                "orocos-kdl (KDL is a test oracle, not linked into the program).\n");
    return 0;
}

const char* const usage =
    "usage: lagrangelab-bench [SCENE...] [--batches N] [--rhs | --derive | --cancel | --render | --typeset | --gui | --process | --linked |\n"
    "                         --entries | --answers | --grade | --urdf | --lesson]\n"
    "                         [--chains A..B] [--cap S] [--form auto|structured|expanded]\n"
    "  median times of B, C, g, forward/inverse dynamics and one simulated second (default scenes:\n"
    "  the PUMA 560, Stanford arm, UR5, Panda and planar 2R); or\n"
    "  --rhs      one right-hand side of the PUMA 560 with no effects, gravity only, all effects\n"
    "  --derive   the whole symbolic derivation per parameter mode\n"
    "  --derive --chains 3..12  structured beside expanded on seeded random chains, with sizes (--cap S per chain)\n"
    "  --cancel   how soon a derivation stops after its cancel flag is set\n"
    "  --render   headless export of 10 s of the PUMA 560 to MP4, render-only frames/s, peak memory\n"
    "  --typeset  one B entry typeset, the 2R and PUMA 560 to PDF, the Panda derived and printed\n"
    "  --gui      the window: edit-to-updated-view latency (2R, PUMA 560), the Panda opened to its\n"
    "             derivation on screen, PUMA 560 animation frames/s, start to first frame; needs a display\n"
    "  --process  whole `lagrangelab derive` processes, every example and format, against their budgets\n"
    "  --linked   the derivation's entry catalogue, every entry evaluated at a state, the run's torques and checks\n"
    "  --entries  B11 and C11 expanded on demand from the structured form; default scenes docs/bench/chain8*.json\n"
    "             (special constant angles beside general ones)\n"
    "  --answers  check-answer of the PUMA 560's b11 as a process and against a built key; 300 checks of a 2R sheet\n"
    "  --grade    lagrangelab grade of 30 students' answer files of 10 entries, each against its own robot\n"
    "  --urdf     lagrangelab import of a 7-joint URDF as a process, and the import alone\n"
    "  --lesson   a lesson's next view on screen in presentation mode, its scene loaded (2R) or not (Panda); needs a display\n"
    "Built in the tree, not installed; docs/benchmarks.md records what it measured.\n";

int run(const std::vector<std::string>& args) {
    const Options options(args, {"batches", "chains", "cap", "form"},
                          {"rhs", "derive", "cancel", "render", "typeset", "gui", "process", "linked", "entries", "answers", "grade", "urdf", "lesson"});
    // --batches N, or each mode's default: a whole number from 1 to 1000 (0 batches have
    // no median).
    const auto batchesOr = [&](int fallback) { return checkedBatches(options.number("batches", fallback), options.text("batches")); };
    std::vector<std::string> scenes = options.positional();
    if (options.has("gui")) return gui(scenes, batchesOr(9));
    if (options.has("lesson")) return lesson(batchesOr(5));
    if (options.has("answers")) return answers(batchesOr(5));
    if (options.has("urdf")) return urdf(batchesOr(9));
    if (options.has("grade")) return grade(batchesOr(5));
    if (options.has("linked")) {
        if (scenes.empty())
            for (const char* name : {"planar_2r", "scara", "stanford_arm", "puma560", "ur5", "panda", "mass_spring_pair_lagrangian"})
                scenes.push_back(example(name));
        return linked(scenes, batchesOr(5));
    }
    if (options.has("entries")) return expandedEntries(scenes.empty() ? benchChains() : scenes, {"B11", "C11"}, batchesOr(3));
    if (options.has("render")) return render(scenes, batchesOr(3));
    if (options.has("typeset")) return typeset(scenes, batchesOr(5));
    if (options.has("form") && !options.has("process")) throw UsageError("--form: only with --process");
    if (options.has("process")) {
        const std::string form = options.text("form", "auto");
        if (form != "auto" && form != "structured" && form != "expanded")
            throw UsageError("--form: expected auto, structured or expanded, got '" + form + "'");
        return process(scenes, batchesOr(7), form);
    }
    if (options.has("chains") && !options.has("derive")) throw UsageError("--chains: only with --derive");
    if (options.has("derive") && options.has("chains"))
        return deriveChains(options.text("chains"), scenes, batchesOr(5), options.number("cap", 20.0));
    if (options.has("derive")) {
        if (scenes.empty())
            for (const char* name : {"planar_2r", "scara", "cart_pole", "puma560", "stanford_arm", "mass_spring_pair_lagrangian"})
                scenes.push_back(example(name));
        return benchDerive(scenes, batchesOr(5));
    }
    if (options.has("cancel")) {
        if (scenes.empty())
            for (const char* name : {"puma560", "stanford_arm", "panda"}) scenes.push_back(example(name));
        return benchCancel(scenes);
    }
    if (options.has("rhs")) {
        if (scenes.empty()) scenes.push_back(example("puma560"));
        return benchRhs(scenes, batchesOr(21));
    }
    return dynamics(scenes, batchesOr(21));
}

}  // namespace
}  // namespace ll::bench

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv + 1, argv + argc);
    for (const std::string& a : args)
        if (a == "--help" || a == "-h") {
            std::fputs(ll::bench::usage, stdout);
            return 0;
        }
    try {
        return ll::bench::run(args);
    } catch (const ll::InputError& e) {
        for (const ll::Diagnostic& d : e.diagnostics())
            if (d.severity == ll::Severity::Error) std::fprintf(stderr, "%s\n", d.toString().c_str());
        return 2;
    } catch (const ll::cli::UsageError& e) {  // in English, as the benchmark's usage and tables are: what()
        std::fprintf(stderr, "error: %s\n%s", e.what(), ll::bench::usage);
        return 2;
    } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
}
