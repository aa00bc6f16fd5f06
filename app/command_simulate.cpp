// `lagrangelab simulate SCENE [--duration T] [--integrator NAME] [--abs-tol X]
// [--rel-tol X] [--dt X] [--output-rate HZ] [--out FILE.csv|FILE.json]`: the trajectory,
// its energies and where the torque goes (core/simulation/torque_parts.hpp) per sample;
// for a controlled scene also the reference, the tracking error and the controller's terms
// (core/simulation/control_history.hpp).
#include <cstdio>
#include <iostream>
#include <optional>

#include <unistd.h>

#include "app/cli_options.hpp"
#include "app/command_usage.hpp"
#include "app/commands.hpp"
#include "app/progress_bar.hpp"
#include "app/scene_loading.hpp"
#include "core/io/trajectory_file.hpp"
#include "core/present/message_text.hpp"
#include "core/simulation/scene_validation.hpp"
#include "core/pipeline/scene_simulation.hpp"
#include "core/model/actuation.hpp"
#include "core/simulation/run_history.hpp"

namespace ll::cli {
namespace {

void printSummary(const Scene& scene, const SimulationSettings& settings, const SimulationResult& r) {
    const SimulationStats& s = r.stats;
    if (s.dt > 0)
        std::fprintf(stderr, "%s: %.6g s simulated with %s (fixed step dt %.6g s)\n", scene.name.c_str(), s.simulatedSeconds,
                     s.integrator.c_str(), s.dt);
    else
        std::fprintf(stderr, "%s: %.6g s simulated with %s (abs_tol %.3g, rel_tol %.3g, first step %.3g s)\n", scene.name.c_str(),
                     s.simulatedSeconds, s.integrator.c_str(), settings.absTol, settings.relTol, settings.dt);
    const double perSecond = s.simulatedSeconds > 0 ? s.cpuSeconds / s.simulatedSeconds : 0;
    std::fprintf(
        stderr,
        "cost: %ld steps (%ld rejected), %ld right-hand-side evaluations, CPU %.3f ms (%.3f ms per simulated second, %.0fx real time)\n",
        s.steps, s.rejectedSteps, s.rhsEvaluations, 1e3 * s.cpuSeconds, 1e3 * perSecond, perSecond > 0 ? 1.0 / perSecond : 0.0);
    if (s.dt > 0) {
        std::fprintf(stderr, "steps: at t_k = k dt");
        if (s.lastStep > 0)
            std::fprintf(stderr, ", then a last shorter step of %.6g s to reach %.6g s (the duration is not a multiple of dt)", s.lastStep,
                         settings.duration);
        if (s.eventSteps > 0) std::fprintf(stderr, "; %ld of them ended early at located stick-slip events", s.eventSteps);
        std::fprintf(stderr, "\n");
        if (s.interpolatedSamples > 0)
            std::fprintf(stderr,
                         "output: %ld of %zu samples lie between step ends: q, qd and W by cubic Hermite "
                         "interpolation from q, qd, qdd at the step ends, energies at the interpolated state\n",
                         s.interpolatedSamples, r.trajectory.size());
    } else if (s.eventSteps > 0) {
        std::fprintf(stderr, "steps: %ld of them ended at a located event or corner (stick-slip, a reference's corner, a torque reaching or leaving its limit)\n",
                     s.eventSteps);
    }
    std::fprintf(stderr, "energy: max |E - E0 - W| = %.3g J, max |dE|/E = %.3g (W: work of friction and torques)\n", s.maxEnergyError,
                 s.maxRelEnergyError);
    if (scene.lagrangian) return;  // its inputs include `forces`: `eval` and `derive` report them
    const int n = scene.robot.dof();
    const std::vector<int> inputs = actuatedJoints(scene.effects, n);
    if (static_cast<int>(inputs.size()) < n) {
        std::vector<std::string> names;
        for (int i = 0; i < n; ++i) names.push_back(r.trajectory.coordinateName(i));
        std::fprintf(stderr, "actuation: %s\n", actuationText(inputs, names).c_str());
    }
}

}  // namespace

int simulateCommand(const Args& args) {
    const Options options(args, {"duration", "integrator", "abs-tol", "rel-tol", "dt", "output-rate", "out"});
    if (options.positional().size() != 1) throw UsageError(usageLine("simulate"));
    Scene scene = loadSceneReportingWarnings(options.positional()[0]);
    SimulationSettings& settings = scene.simulation;
    settings.duration = options.number("duration", settings.duration);
    settings.integrator = options.text("integrator", settings.integrator);
    settings.absTol = options.number("abs-tol", settings.absTol);
    settings.relTol = options.number("rel-tol", settings.relTol);
    settings.dt = options.number("dt", settings.dt);
    settings.outputRate = options.number("output-rate", settings.outputRate);
    requireValidSceneFrom(scene, options.positional()[0]);  // the command-line values too

    ProgressBar bar(::isatty(STDERR_FILENO) && settings.duration > 0);
    const SimulationInput input = prepareSimulation(scene);
    const SimulationResult result = ll::simulate(input, settings, [&](double f) { bar(f); });
    bar(1.0);
    // Where the torque goes, and the controller's reference, error and terms (and its
    // Lyapunov function), as more columns; none when B is singular somewhere on the run.
    const RunHistory history = runHistory(input, result.trajectory);
    const std::optional<TorqueHistory>& torques = history.torques;
    TorqueColumns columns = torques ? torqueColumns(scene, *torques) : TorqueColumns{};
    if (history.control) columns.control = &*history.control;
    if (options.has("out")) saveTrajectory(result, options.text("out"), columns);
    else writeTrajectoryCsv(result.trajectory, std::cout, columns);
    printSummary(scene, settings, result);
    if (torques)
        std::fprintf(stderr, "torques: largest |B qdd + C qd + g - Q| = %.3g (%.3g of the largest term, %.3g)\n", torques->largestResidual,
                     torques->scale > 0 ? torques->largestResidual / torques->scale : 0.0, torques->scale);
    const present::Language language = presentation().language;
    if (result.status == SimulationStatus::Failed) {
        std::fprintf(stderr, "%s\n", usageErrorLine(usageMessage(UsageId::SimulationStopped, result.message), language).c_str());
        return 3;
    }
    if (!result.message.empty())
        std::fprintf(stderr, "%s%s\n", present::messageText(MessageId::WarningLine, language).c_str(),
                     present::messageText(result.message, language).c_str());
    return 0;
}

}  // namespace ll::cli
