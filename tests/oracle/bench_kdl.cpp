// `build/tests/lagrangelab_bench_kdl [SCENE...] [--batches N]`: our B, C, g, forward and
// inverse dynamics beside KDL's solvers, timed in the same run on the same seeded random
// states as `lagrangelab bench` (app/bench_timing.hpp). KDL is a test oracle: the
// program does not link it, so its timings live here, beside the tests that use it.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "app/bench/bench_timing.hpp"
#include "core/io/scene_file.hpp"
#include "tests/oracle/kdl_chain.hpp"

int main(int argc, char** argv) {
    using namespace ll;
    using namespace ll::cli;
    std::vector<std::string> scenes;
    int batches = 21;  // as `lagrangelab bench`
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--batches" && i + 1 < argc) {
            char* end = nullptr;
            const char* typed = argv[++i];
            const double n = std::strtod(typed, &end);
            try {
                batches = checkedBatches(*end == '\0' && end != typed ? n : NAN, typed);
            } catch (const std::invalid_argument& e) {
                std::fprintf(stderr, "error: %s\n", e.what());
                return 2;
            }
        } else if (arg.rfind("--", 0) == 0) {
            std::fprintf(stderr, "error: %s: unknown option (usage: lagrangelab_bench_kdl [SCENE...] [--batches N])\n", arg.c_str());
            return 2;
        } else {
            scenes.push_back(arg);
        }
    }
    if (scenes.empty())
        for (const char* name : {"puma560", "stanford_arm", "ur5", "panda", "planar_2r"})
            scenes.push_back(std::string(LL_EXAMPLES_DIR) + "/" + name + ".json");

    std::printf("median time per call [µs] over %d batches of random states\n\n", batches);
    std::printf("%-24s %2s | %7s %7s %7s %7s %7s | %9s %9s %9s %9s %9s\n", "robot", "n", "B", "C", "g", "FD", "RNEA", "KDL B", "KDL Cq̇",
                "KDL g", "KDL FD", "KDL RNEA");
    for (const std::string& path : scenes) {
        Scene scene;
        try {
            scene = loadScene(path).scene;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "error: %s: %s\n", path.c_str(), e.what());
            return 2;
        }
        const RobotModel& robot = scene.robot;
        if (scene.lagrangian || robot.dof() == 0) {
            std::fprintf(stderr, "error: %s: not a robot (KDL needs a chain)\n", path.c_str());
            return 2;
        }
        const States s = randomStates(robot, 64);
        const DynamicsTimes ours = dynamicsTimes(robot, scene.effects, s, batches);
        KdlOracle kdl(robot, scene.effects, KdlChainLayout::Compact);
        const int count = static_cast<int>(s.q.size());
        const auto kdlTime = [&](auto&& solve) {
            return medianMicros(batches, count, [&](int k) {
                kdl.setState(s.q[k], s.qd[k]);
                kdl.setTorque(s.tau[k]);
                kdl.setAcceleration(s.tau[k]);
                solve();
            });
        };
        const double setOnly = kdlTime([] {});
        const double kB = kdlTime([&] { kdl.kdlMassMatrix(); }) - setOnly;
        const double kC = kdlTime([&] { kdl.kdlCoriolis(); }) - setOnly;
        const double kG = kdlTime([&] { kdl.kdlGravity(); }) - setOnly;
        const double kFD = kdlTime([&] { kdl.kdlForwardDynamics(); }) - setOnly;
        const double kID = kdlTime([&] { kdl.kdlInverseDynamics(); }) - setOnly;
        std::printf("%-24.24s %2d | %7.3f %7.3f %7.3f %7.3f %7.3f | %9.3f %9.3f %9.3f %9.3f %9.3f\n", scene.name.c_str(), robot.dof(),
                    ours.B, ours.C, ours.g, ours.FD, ours.RNEA, kB, kC, kG, kFD, kID);
    }
    std::printf("\nB: kinematics + CRBA; C: + Christoffel matrix; FD: q̈ = B⁻¹(Q − C q̇ − g); RNEA: inverse dynamics.\n"
                "KDL: ChainDynParam JntToMass/JntToCoriolis/JntToGravity, ChainFdSolver_RNE, ChainIdSolver_RNE\n"
                "(copying the inputs into KDL arrays is measured separately and subtracted).\n");
    return 0;
}
