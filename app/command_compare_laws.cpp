// `lagrangelab compare-laws SCENE [--duration T] [--format text|json] [--out FILE.svg|png]`:
// a controlled scene run under each law (core/pipeline/law_comparison.hpp) with its own
// gains, reference, controller model and limits, as a table: RMS and largest tracking error,
// largest torque, the actuators' work, the time spent saturated; a law the robot cannot carry
// out says why. With --out also the plot of the error and the torque against time.
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/cli_options.hpp"
#include "app/command_usage.hpp"
#include "app/commands.hpp"
#include "app/offscreen_gui.hpp"
#include "app/scene_loading.hpp"
#include "core/io/trajectory_file.hpp"
#include "core/math/vector_list.hpp"
#include "core/model/quantity_units.hpp"
#include "core/pipeline/law_comparison.hpp"
#include "core/present/message_text.hpp"
#include "core/simulation/scene_validation.hpp"
#include "ui/paint/law_comparison_plot.hpp"

namespace ll::cli {
namespace {

// "rad", "m", or "rad, m" when the robot has both kinds of joint.
std::string unitsOf(const Scene& scene, bool torque) {
    bool revolute = false, prismatic = false;
    for (const Joint& j : scene.robot.joints) (j.dh.type == JointType::Revolute ? revolute : prismatic) = true;
    const auto unit = [&](bool r) { return torque ? forceUnit(r) : coordinateUnit(r); };
    if (revolute && prismatic) return unit(true) + ", " + unit(false);
    return unit(revolute);
}

std::string describeControl(const Control& c) {
    std::string text = std::string(toString(c.reference.kind)) + " reference";
    if (c.model.payloadMass > 0) text += ", a payload of " + formatValue(c.model.payloadMass) + " kg the robot does not carry in the controller's model";
    if (c.model.scale.size() > 0) text += ", the controller's links scaled";
    if (c.torqueLimit.size() > 0) text += ", torques limited";
    return text;
}

void printTable(const Scene& scene, const std::vector<LawRun>& runs) {
    const present::Language language = presentation().language;
    std::printf("%s: %.6g s under each law (%s)\n", scene.name.c_str(), scene.simulation.duration,
                describeControl(*scene.effects.control).c_str());
    const std::string e = unitsOf(scene, false), tau = unitsOf(scene, true);
    std::printf("%-16s %14s %14s %14s %11s %14s\n", "law", ("RMS e [" + e + "]").c_str(), ("max |e| [" + e + "]").c_str(),
                ("max |tau| [" + tau + "]").c_str(), "work [J]", "saturated [s]");
    for (const LawRun& r : runs) {
        if (!r.impossible.empty()) {
            std::printf("%-16s not possible: %s\n", toString(r.law), present::messageText(r.impossible, language).c_str());
            continue;
        }
        const TrackingSummary& s = r.summary;
        if (s.rmsError.size() == 0) {
            std::printf("%-16s stopped: %s\n", toString(r.law), present::messageText(r.result.message, language).c_str());
            continue;
        }
        std::printf("%-16s %14.4g %14.4g %14.4g %11.4g %14.4g%s\n", toString(r.law), s.rmsError.maxCoeff(), s.maxError.maxCoeff(),
                    s.maxTorque.maxCoeff(), s.energySpent, r.saturatedSeconds,
                    r.result.status == SimulationStatus::Failed ? "  (stopped early)" : "");
    }
    std::printf("RMS e and max |e|: the largest joint's; work: the integral of sum |tau_i qd_i| dt (none given back); "
                "saturated: the time the most saturated joint spent at its limit\n");
}

void printJson(const Scene& scene, const std::vector<LawRun>& runs) {
    nlohmann::ordered_json j;
    j["scene"] = scene.name;
    j["duration"] = scene.simulation.duration;
    j["units"] = {{"error", coordinateUnits(scene)}, {"energy_spent", "J"}, {"saturated_seconds", "s"}};
    nlohmann::ordered_json laws = nlohmann::ordered_json::array();
    for (const LawRun& r : runs) {
        nlohmann::ordered_json law;
        law["law"] = toString(r.law);
        if (!r.impossible.empty()) {
            law["possible"] = false;
            law["why"] = r.impossible.english();
        } else {
            law["possible"] = true;
            law["completed"] = r.result.status == SimulationStatus::Completed;
            if (!r.result.message.empty()) law["message"] = r.result.message.english();
            if (r.summary.rmsError.size() > 0) {
                law["rms_error"] = listOf(r.summary.rmsError);
                law["max_error"] = listOf(r.summary.maxError);
                law["max_torque"] = listOf(r.summary.maxTorque);
                law["energy_spent"] = r.summary.energySpent;
                law["saturated_seconds"] = r.saturatedSeconds;
            }
        }
        laws.push_back(law);
    }
    j["laws"] = laws;
    std::cout << j.dump(1) << '\n';
}

}  // namespace

int compareLawsCommand(const Args& args) {
    const Options options(args, {"duration", "format", "out"});
    if (options.positional().size() != 1) throw UsageError(usageLine("compare-laws"));
    const std::string format = options.text("format", "text");
    if (format != "text" && format != "json") throw UsageError(UsageId::ExpectedOneOf, "format", "text", "json", format);
    const std::string plot = options.text("out");
    if (!plot.empty() && !plot.ends_with(".svg") && !plot.ends_with(".png")) throw UsageError(UsageId::PlotFileType, plot);
    const std::string path = options.positional()[0];
    Scene scene = loadSceneReportingWarnings(path);
    scene.simulation.duration = options.number("duration", scene.simulation.duration);
    requireValidSceneFrom(scene, path);
    if (scene.lagrangian || !scene.effects.control) throw UsageError(UsageId::CompareLawsNeedsControl, path);
    const std::vector<LawRun> runs = compareLaws(scene);
    if (format == "json") printJson(scene, runs);
    else printTable(scene, runs);
    std::fflush(stdout);  // the table before the plot's line on stderr
    if (!plot.empty()) {
        const auto app = makeGuiApplication();  // fonts
        QString error;
        const ui::LawComparisonPlot picture{scene.name, unitsOf(scene, false), unitsOf(scene, true), &runs};
        if (!ui::saveLawComparisonPlot(picture, QString::fromStdString(plot), &error)) throw std::runtime_error(error.toStdString());
        std::fprintf(stderr, "plot written to %s\n", plot.c_str());
    }
    return 0;
}

}  // namespace ll::cli
