// lagrangelab-bench --linked: what the derivation linked to the motion costs (issue 35):
// the derivation with and without its entry catalogue (the entries traced to their links
// and compiled), one evaluation of every entry at a state (what the window does per
// frame), and the run's analysis (torque parts and properties) on the simulation's worker.
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "app/bench/bench.hpp"
#include "app/bench/bench_timing.hpp"
#include "app/scene_loading.hpp"
#include "core/pipeline/display_derivation.hpp"
#include "core/pipeline/scene_simulation.hpp"
#include "core/simulation/model_properties.hpp"
#include "core/simulation/torque_parts.hpp"

namespace ll::bench {
namespace {

using cli::loadSceneReportingWarnings;
using cli::median;
using cli::ms;
using Clock = std::chrono::steady_clock;

}  // namespace

int linked(const std::vector<std::string>& scenes, int runs) {
    std::printf("%-44s %-10s %8s %8s %8s %7s %7s %9s %9s %9s\n", "scene", "form", "derive", "+catalog", "entries", "outputs", "instr",
                "eval [us]", "torques", "checks");
    std::printf("%-44s %-10s %8s %8s %8s %7s %7s %9s %9s %9s\n", "", "", "[ms]", "[ms]", "", "", "", "all", "[ms]", "[ms]");
    for (const std::string& path : scenes) {
        const Scene scene = loadSceneReportingWarnings(path);
        std::vector<double> plain, withCatalogue, evaluation, torques, checks;
        std::shared_ptr<const EntryCatalogue> catalogue;
        std::string form;
        for (int r = 0; r < runs; ++r) {
            DocumentRequest request;
            auto t0 = Clock::now();
            const DerivedDocument a = deriveDisplay(scene, request);
            auto t1 = Clock::now();
            request.catalogue = true;
            const DerivedDocument b = deriveDisplay(scene, request);
            auto t2 = Clock::now();
            plain.push_back(ms(t0, t1));
            withCatalogue.push_back(ms(t1, t2));
            catalogue = b.catalogue;
            form = b.display->form.english();
        }
        const SimulationInput input = prepareSimulation(scene);
        const SimulationResult run = ll::simulate(input, scene.simulation);
        const Trajectory& tr = run.trajectory;
        std::vector<double> values;
        for (int r = 0; r < runs; ++r) {
            auto t0 = Clock::now();
            for (std::size_t k = 0; k < tr.size(); ++k) catalogue->evaluate(tr.q[k].data(), tr.qd[k].data(), tr.t[k], values);
            auto t1 = Clock::now();
            evaluation.push_back(1000 * ms(t0, t1) / static_cast<double>(tr.size()));
            const TorqueHistory history = torqueHistory(input, tr);
            auto t2 = Clock::now();
            const ModelProperties properties = checkModelProperties(input, tr);
            auto t3 = Clock::now();
            torques.push_back(ms(t1, t2));
            checks.push_back(ms(t2, t3));
        }
        std::printf("%-44.44s %-10s %8.1f %8.1f %8zu %7d %7d %9.1f %9.1f %9.1f\n", scene.name.c_str(), form.c_str(), median(plain),
                    median(withCatalogue) - median(plain), catalogue->entries.size(), catalogue->values.outputCount(),
                    catalogue->values.instructionCount(), median(evaluation), median(torques), median(checks));
    }
    std::printf("\nderive: the display document as the window derives it (auto form); +catalog: what tracing and compiling\n"
                "its entries adds; eval: every entry at one state of the run (the window evaluates them once per frame);\n"
                "torques, checks: the run's torque parts and model properties over its samples (the simulation's worker).\n");
    return 0;
}

}  // namespace ll::bench
