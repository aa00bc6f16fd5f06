#include "core/simulation/work_precision.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "core/simulation/integrators.hpp"
#include "core/simulation/simulate.hpp"

namespace ll {

const char* workPrecisionDefinitions() {
    return "error: final-state error in the units of the tolerances (abs_tol = rel_tol = tol), "
           "max over q_i, qd_i at t = T of |x_i - x_ref,i| / (1 + |x_ref,i|), against a reference solution "
           "whose own error is estimated (its distance to the same method at 10x its tolerance); an error at or "
           "below that estimate only says the run is at least as good as the reference. energy drift: max over "
           "the run of |E - E0 - W| (W: work of friction and torques) relative to the energy scale of the "
           "motion. CPU time: median over repeats, this thread only.";
}

Eigen::VectorXd finalState(const Trajectory& trajectory) {
    const int n = trajectory.n;
    Eigen::VectorXd x(2 * n);
    x << trajectory.q.back(), trajectory.qd.back();
    return x;
}

double finalStateError(const Eigen::VectorXd& x, const Eigen::VectorXd& reference) {
    return ((x - reference).cwiseAbs().array() / (1.0 + reference.cwiseAbs().array())).maxCoeff();
}

namespace {

std::string describe(const std::string& integrator, bool adaptive, double setting) {
    std::ostringstream s;
    s << integrator << (adaptive ? " tol " : " dt ") << setting;
    return s.str();
}

void requirePositive(const std::vector<double>& values, const char* what) {
    for (double v : values)
        if (!(std::isfinite(v) && v > 0)) throw std::invalid_argument(std::string(what) + " must be finite numbers > 0");
}

}  // namespace

WorkPrecisionResult runWorkPrecision(const SimulationInput& input, const WorkPrecisionSettings& settings,
                                     const WorkPrecisionProgress& progress, const std::atomic<bool>* cancel) {
    const Scene& scene = input.scene;
    std::vector<std::string> names = settings.integrators;
    if (names.empty())
        for (const IntegratorInfo& info : integratorCatalogue()) names.push_back(info.name);
    for (const std::string& name : names)
        if (!findIntegrator(name)) throw std::invalid_argument("unknown integrator '" + name + "' (known: " + integratorNames() + ")");
    if (!findIntegrator(settings.referenceIntegrator) || !findIntegrator(settings.referenceIntegrator)->adaptive)
        throw std::invalid_argument("the reference integrator must be an adaptive one, got '" + settings.referenceIntegrator + "'");
    requirePositive(settings.tolerances, "tolerances");
    requirePositive(settings.steps, "steps");
    if (settings.tolerances.empty() || settings.steps.empty())
        throw std::invalid_argument("tolerances and steps need at least one value each");
    if (settings.repeats < 1) throw std::invalid_argument("repeats must be at least 1");

    const double cpuStart = threadCpuSeconds();
    WorkPrecisionResult result;
    result.scene = scene.name;
    result.duration = settings.duration > 0 ? settings.duration : scene.simulation.duration;

    SimulationSettings base = scene.simulation;
    base.duration = result.duration;
    base.outputRate = std::max(settings.outputRate, 1.0 / result.duration);

    // Work plan: the reference (2 runs), then every point × repeats.
    long totalRuns = 2, doneRuns = 0;
    for (const std::string& name : names)
        totalRuns +=
            settings.repeats * static_cast<long>(findIntegrator(name)->adaptive ? settings.tolerances.size() : settings.steps.size());
    const auto report = [&](const Message& what) {
        if (progress) progress(static_cast<double>(doneRuns) / static_cast<double>(totalRuns), what);
    };
    const auto cancelled = [&] { return cancel && cancel->load(std::memory_order_relaxed); };
    const auto stopCancelled = [&] {
        result.status = SimulationStatus::Cancelled;
        result.message = message(MessageId::CancelledAfterSettings, result.points.size());
        result.cpuSeconds = threadCpuSeconds() - cpuStart;
        return result;
    };

    // Reference at the tightest setting with a high-order method, and its own error.
    WorkPrecisionReference& ref = result.reference;
    ref.integrator = settings.referenceIntegrator;
    ref.tolerance = settings.referenceTolerance > 0
                        ? settings.referenceTolerance
                        : std::max(*std::min_element(settings.tolerances.begin(), settings.tolerances.end()) / 100, 1e-14);
    SimulationSettings refSettings = base;
    refSettings.integrator = ref.integrator;
    refSettings.absTol = refSettings.relTol = ref.tolerance;
    refSettings.detectStiffness = false;  // however stiff the scene, the reference resolves it
    report(message(MessageId::SweepReference, describe(ref.integrator, true, ref.tolerance)));
    const SimulationResult reference = simulate(input, refSettings, {}, cancel);
    ++doneRuns;
    if (reference.status == SimulationStatus::Cancelled) return stopCancelled();
    if (reference.status != SimulationStatus::Completed) {
        result.status = SimulationStatus::Failed;
        result.message = message(MessageId::ReferenceSolutionFailed, describe(ref.integrator, true, ref.tolerance), reference.message);
        result.cpuSeconds = threadCpuSeconds() - cpuStart;
        return result;
    }
    ref.finalState = finalState(reference.trajectory);
    ref.maxRelEnergyDrift = reference.stats.maxRelEnergyError;
    ref.cpuSeconds = reference.stats.cpuSeconds;
    SimulationSettings looser = refSettings;
    looser.absTol = looser.relTol = 10 * ref.tolerance;
    report(message(MessageId::SweepReferenceErrorEstimate, describe(ref.integrator, true, looser.absTol)));
    const SimulationResult check = simulate(input, looser, {}, cancel);
    ++doneRuns;
    if (check.status == SimulationStatus::Cancelled) return stopCancelled();
    ref.estimatedError = check.status == SimulationStatus::Completed ? finalStateError(finalState(check.trajectory), ref.finalState)
                                                                     : std::numeric_limits<double>::infinity();

    for (const std::string& name : names) {
        const IntegratorInfo& info = *findIntegrator(name);
        for (double setting : info.adaptive ? settings.tolerances : settings.steps) {
            WorkPrecisionPoint point;
            point.integrator = name;
            point.adaptive = info.adaptive;
            point.setting = setting;
            SimulationSettings s = base;
            s.integrator = name;
            if (info.adaptive) {
                s.absTol = s.relTol = setting;
                s.dt = std::min(base.dt, 1e-3);
            } else {
                s.dt = setting;
            }
            std::vector<double> cpu;
            for (int r = 0; r < settings.repeats; ++r) {
                if (cancelled()) return stopCancelled();
                report(literal(describe(name, info.adaptive, setting)));
                const SimulationResult run = simulate(input, s, {}, cancel);
                ++doneRuns;
                if (run.status == SimulationStatus::Cancelled) return stopCancelled();
                cpu.push_back(run.stats.cpuSeconds);
                if (r == 0) {
                    point.completed = run.status == SimulationStatus::Completed;
                    point.message = run.message;
                    point.maxRelEnergyDrift = run.stats.maxRelEnergyError;
                    point.rhsEvaluations = run.stats.rhsEvaluations;
                    point.steps = run.stats.steps;
                    point.rejectedSteps = run.stats.rejectedSteps;
                    point.step = info.adaptive ? (run.stats.steps > 0 ? run.stats.simulatedSeconds / run.stats.steps : 0.0) : run.stats.dt;
                    point.lastStep = run.stats.lastStep;
                    if (point.completed) {
                        point.finalError = finalStateError(finalState(run.trajectory), ref.finalState);
                        point.atReferenceFloor = point.finalError <= ref.estimatedError;
                    }
                }
                if (!point.completed) {  // a failure is not timed again
                    doneRuns += settings.repeats - 1 - r;
                    break;
                }
            }
            std::sort(cpu.begin(), cpu.end());
            point.cpuSeconds = cpu[cpu.size() / 2];
            result.points.push_back(point);
        }
    }
    report(MessageId::SweepDone);
    if (progress) progress(1.0, MessageId::SweepDone);
    result.cpuSeconds = threadCpuSeconds() - cpuStart;
    return result;
}

}  // namespace ll
