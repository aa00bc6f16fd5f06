// `lagrangelab check SCENE [--duration T] [--format text|json]`: the properties every
// Euler–Lagrange model has, checked along a simulated run of the scene
// (core/simulation/model_properties.hpp): each with its worst value, where it occurs,
// its tolerance and a sentence that says what it means; for a controlled scene also how
// well it tracked (RMS and largest error, torques, saturated fraction). Exit 0 when every property
// holds, 1 when one fails, 2 for bad input.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/cli_options.hpp"
#include "app/command_usage.hpp"
#include "app/commands.hpp"
#include "app/scene_loading.hpp"
#include "core/math/vector_list.hpp"
#include "core/pipeline/scene_simulation.hpp"
#include "core/io/trajectory_file.hpp"
#include "core/model/quantity_units.hpp"
#include "core/simulation/run_history.hpp"
#include "core/simulation/model_properties.hpp"
#include "core/simulation/scene_validation.hpp"

namespace ll::cli {
namespace {

// (0.1, −0.25, 3)
std::string vectorText(const Eigen::VectorXd& v) {
    std::string s = "(";
    char buffer[32];
    for (int i = 0; i < v.size(); ++i) {
        std::snprintf(buffer, sizeof buffer, "%s%.4g", i ? ", " : "", v[i]);
        s += buffer;
    }
    return s + ")";
}

std::string numberText(double v, const std::string& unit) {
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%.3g", v);
    return unit.empty() ? buffer : std::string(buffer) + " " + unit;
}

// The joint (0-based) where a per-joint value is largest.
Eigen::Index largestAt(const Eigen::VectorXd& v) {
    Eigen::Index at = 0;
    v.maxCoeff(&at);
    return at;
}

void printTracking(const Scene& scene, const ControlHistory& control) {
    const TrackingSummary& s = control.summary;
    const std::vector<std::string> units = coordinateUnits(scene);
    std::printf("  tracking (%s, e = q_ref - q):\n", toString(scene.effects.control->law));
    for (int i = 0; i < s.rmsError.size(); ++i)
        std::printf("        joint %d: RMS e = %s, max |e| = %s, max |tau| = %s%s\n", i + 1, numberText(s.rmsError[i], units[i]).c_str(),
                    numberText(s.maxError[i], units[i]).c_str(),
                    numberText(s.maxTorque[i], forceUnit(scene.robot.joints[i].dh.type == JointType::Revolute)).c_str(),
                    s.saturatedFraction[i] > 0 ? (", saturated " + numberText(100 * s.saturatedFraction[i], "%")).c_str() : "");
    const Eigen::Index worst = largestAt(s.saturatedFraction);
    if (scene.effects.control->torqueLimit.size() == 0) std::printf("        no torque limits");
    else
        std::printf("        largest saturated fraction: %s (joint %d)", numberText(s.saturatedFraction[worst], "").c_str(),
                    static_cast<int>(worst) + 1);
    std::printf("; actuators' work %s\n", numberText(s.energySpent, "J").c_str());
    if (control.lyapunov)
        std::printf("        V = 1/2 qd'B qd + 1/2 e'Kp e%s: max |dV/dt + qd'Kd qd| = %s of max qd'Kd qd "
                    "(0 when the controller's g is the robot's and nothing else acts: qd'(Bdot - 2C)qd = 0)\n",
                    scene.effects.control->law == ControlLaw::Pd ? " + Epot(q) - Epot(q_ref)" : "",
                    numberText(control.lyapunov->largestDeparture, "").c_str());
}

nlohmann::ordered_json trackingJson(const Scene& scene, const ControlHistory& control) {
    const TrackingSummary& s = control.summary;
    nlohmann::ordered_json j;
    j["law"] = toString(scene.effects.control->law);
    j["rms_error"] = listOf(s.rmsError);
    j["max_error"] = listOf(s.maxError);
    j["max_torque"] = listOf(s.maxTorque);
    j["saturated_fraction"] = listOf(s.saturatedFraction);
    j["largest_saturated_fraction"] = s.saturatedFraction.maxCoeff();
    j["energy_spent"] = s.energySpent;
    j["units"] = {{"rms_error", coordinateUnits(scene)}, {"energy_spent", "J"}};
    if (control.lyapunov) j["lyapunov_departure"] = control.lyapunov->largestDeparture;
    return j;
}

void printText(const Scene& scene, const SimulationResult& run, const ModelProperties& properties, const ControlHistory* control) {
    std::printf("%s: %.6g s simulated with %s, %zu samples checked\n", scene.name.c_str(), run.stats.simulatedSeconds,
                run.stats.integrator.c_str(), run.trajectory.size());
    for (const PropertyCheck& c : properties.checks) {
        if (!c.applies) {
            std::printf("  n/a   %s (%s): does not apply to a typed Lagrangian\n", c.title.c_str(), c.key.c_str());
            continue;
        }
        std::printf("  %s  %s\n        %s = %s (%s %s)", c.passed ? "PASS" : "FAIL", c.title.c_str(), c.key.c_str(),
                    numberText(c.value, c.unit).c_str(), c.atLeast ? "must be above" : "tolerance",
                    numberText(c.tolerance, c.unit).c_str());
        if (c.q.size() > 0) std::printf(", worst at t = %.4g s, q = %s", c.time, vectorText(c.q).c_str());
        std::printf("\n        %s\n", c.explanation.c_str());
    }
    if (control) printTracking(scene, *control);
    if (run.status == SimulationStatus::Failed)  // the report is in English, as its checks are
        std::printf("the simulation stopped early: %s\n", run.message.english().c_str());
    std::printf("%s\n", properties.passed() ? "passed: every property holds" : "failed: a property does not hold");
}

void printJson(const Scene& scene, const SimulationResult& run, const ModelProperties& properties, const ControlHistory* control) {
    nlohmann::ordered_json j;
    j["scene"] = scene.name;
    j["simulated_seconds"] = run.stats.simulatedSeconds;
    j["samples"] = run.trajectory.size();
    nlohmann::ordered_json details = nlohmann::ordered_json::array();
    for (const PropertyCheck& c : properties.checks) {
        // a value that does not apply, or is not finite (B singular), is null
        j[c.key] = c.applies && std::isfinite(c.value) ? nlohmann::ordered_json(c.value) : nlohmann::ordered_json();
        nlohmann::ordered_json d;
        d["key"] = c.key;
        d["title"] = c.title;
        d["explanation"] = c.explanation;
        d["applies"] = c.applies;
        if (c.applies) {
            d["value"] = std::isfinite(c.value) ? nlohmann::ordered_json(c.value) : nlohmann::ordered_json();
            d["tolerance"] = c.tolerance;
            d["bound"] = c.atLeast ? "above" : "at most";
            d["unit"] = c.unit;
            d["passed"] = c.passed;
            d["time"] = c.time;
            d["q"] = listOf(c.q);
        }
        details.push_back(d);
    }
    j["passed"] = properties.passed();
    if (run.status == SimulationStatus::Failed) j["simulation_stopped"] = run.message.english();
    j["checks"] = details;
    if (control) j["tracking"] = trackingJson(scene, *control);
    std::cout << j.dump(1) << '\n';
}

}  // namespace

int checkCommand(const Args& args) {
    const Options options(args, {"duration", "format"});
    if (options.positional().size() != 1) throw UsageError(usageLine("check"));
    const std::string format = options.text("format", "text");
    if (format != "text" && format != "json") throw UsageError(UsageId::ExpectedOneOf, "format", "text", "json", format);
    Scene scene = loadSceneReportingWarnings(options.positional()[0]);
    scene.simulation.duration = options.number("duration", scene.simulation.duration);
    requireValidSceneFrom(scene, options.positional()[0]);
    const SimulationInput input = prepareSimulation(scene);
    const SimulationResult run = ll::simulate(input, scene.simulation);
    if (run.trajectory.size() == 0) {
        const UsageMessage none = usageMessage(UsageId::SimulationGaveNoSamples, options.positional()[0], run.message);
        std::fprintf(stderr, "%s\n", usageErrorLine(none, presentation().language).c_str());
        return 1;
    }
    const ModelProperties properties = checkModelProperties(input, run.trajectory);
    // A controlled scene: how well it tracked (a report; it does not decide the exit code).
    std::optional<RunHistory> history;
    if (!scene.lagrangian && scene.effects.control) history = runHistory(input, run.trajectory);
    const ControlHistory* tracking = history && history->control ? &*history->control : nullptr;
    if (format == "json") printJson(scene, run, properties, tracking);
    else printText(scene, run, properties, tracking);
    return properties.passed() && run.status != SimulationStatus::Failed ? 0 : 1;
}

}  // namespace ll::cli
