// `lagrangelab accuracy SCENE [--integrators a,b,...] [--tolerances 1e-3..1e-12]
// [--steps ...] [--duration T] [--repeats N] [--reference-tol X] [--out plot.svg|png]
// [--csv FILE]`: the work–precision analysis of core/simulation/work_precision.hpp as a
// table, a CSV file and a log–log plot rendered headless (app/accuracy_plot.cpp).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>

#include <unistd.h>

#include "app/cli_options.hpp"
#include "app/command_usage.hpp"
#include "app/commands.hpp"
#include "app/scene_loading.hpp"
#include "core/simulation/scene_validation.hpp"
#include "core/io/atomic_file.hpp"
#include "core/model/utf8_text.hpp"
#include "core/present/message_text.hpp"
#include "core/simulation/integrators.hpp"
#include "core/pipeline/scene_simulation.hpp"

namespace ll::cli {
namespace {

// "1e-3..1e-12": every decade from one end to the other; otherwise "a,b,c".
std::vector<double> parseSettings(const std::string& option, const std::string& text) {
    std::vector<double> values;
    if (const size_t dots = text.find(".."); dots != std::string::npos) {
        const double a = parseNumber(option, text.substr(0, dots)), b = parseNumber(option, text.substr(dots + 2));
        if (!(a > 0 && b > 0)) throw UsageError(UsageId::RangeNeedsPositive, option, text);
        const double la = std::log10(a), lb = std::log10(b);
        const int count = static_cast<int>(std::floor(std::abs(lb - la) + 1e-9));
        for (int k = 0; k <= count; ++k) values.push_back(a * std::pow(10.0, la <= lb ? k : -k));
        return values;
    }
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        values.push_back(parseNumber(option, item));
        if (!(values.back() > 0)) throw UsageError(UsageId::ValuesNotPositive, option, item);
    }
    if (values.empty()) throw UsageError(UsageId::NoValues, option, text);
    return values;
}

// `text` cut or padded to `width` characters (a Danish letter is two bytes: never half of one).
std::string fitted(const std::string& text, std::size_t width) {
    std::string out;
    std::size_t count = 0;
    for (std::size_t at = 0; at < text.size() && count < width; ++count) {
        const std::size_t bytes = decodeUtf8(text, at).bytes;
        out.append(text, at, bytes);
        at += bytes;
    }
    return out.append(width - count, ' ');
}

std::vector<std::string> parseNames(const std::string& text) {
    std::vector<std::string> names;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ','))
        if (!item.empty()) {
            if (!findIntegrator(item)) throw UsageError(UsageId::UnknownIntegrator, item, integratorNames());
            names.push_back(item);
        }
    return names;
}

void writeCsv(const WorkPrecisionResult& r, std::ostream& out) {
    out.precision(10);
    out << "integrator,adaptive,setting,completed,final_error,at_reference_floor,max_rel_energy_drift,cpu_seconds,"
           "rhs_evaluations,steps,rejected_steps,step_seconds,last_step,message\n";
    out << r.reference.integrator << ",1," << r.reference.tolerance << ",1," << r.reference.estimatedError << ",1,"
        << r.reference.maxRelEnergyDrift << "," << r.reference.cpuSeconds << ",,,,,,\"reference (error: its own estimate)\"\n";
    for (const WorkPrecisionPoint& p : r.points) {
        std::string message = p.message.english();
        for (char& c : message)
            if (c == '"') c = '\'';
        out << p.integrator << "," << p.adaptive << "," << p.setting << "," << p.completed << "," << (p.completed ? p.finalError : NAN)
            << "," << p.atReferenceFloor << "," << p.maxRelEnergyDrift << "," << p.cpuSeconds << "," << p.rhsEvaluations << "," << p.steps
            << "," << p.rejectedSteps << "," << p.step << "," << p.lastStep << ",\"" << message << "\"\n";
    }
}

void printTable(const WorkPrecisionResult& r) {
    std::printf("work-precision of %s over %g s\n%s\n\n", r.scene.c_str(), r.duration, workPrecisionDefinitions());
    if (r.status == SimulationStatus::Failed) return;  // the reference failed: main() says why
    std::printf("reference: %s at tol %.1e, its own error estimate %.2e, energy drift %.2e, CPU %.1f ms\n\n",
                r.reference.integrator.c_str(), r.reference.tolerance, r.reference.estimatedError, r.reference.maxRelEnergyDrift,
                1e3 * r.reference.cpuSeconds);
    std::printf("%-17s %-13s %10s %10s %10s %10s %9s %8s %10s  %s\n", "integrator", "setting", "error", "drift", "CPU [ms]", "rhs evals",
                "steps", "rejected", "dt [s]", "note");
    for (const WorkPrecisionPoint& p : r.points) {
        char setting[32], step[32], last[48] = "";
        std::snprintf(setting, sizeof setting, "%s %.0e", p.adaptive ? "tol" : "dt ", p.setting);
        // the step taken: a fixed-step method's dt, an adaptive one's mean step (~)
        std::snprintf(step, sizeof step, "%s%.2e", p.adaptive ? "~" : "", p.step);
        if (p.lastStep > 0) std::snprintf(last, sizeof last, "last step %.3g s; ", p.lastStep);
        std::string note = last;
        if (!p.completed) {
            const std::string why = p.message.english();  // the table is in English
            note += "stopped: " + why.substr(0, why.find(':'));
            std::printf("%-17s %-13s %10s %10s %10.2f %10ld %9ld %8ld %10s  %s\n", p.integrator.c_str(), setting, "-", "-",
                        1e3 * p.cpuSeconds, p.rhsEvaluations, p.steps, p.rejectedSteps, step, note.c_str());
            continue;
        }
        if (p.atReferenceFloor) note += "at the reference's accuracy";
        std::printf("%-17s %-13s %10.2e %10.2e %10.2f %10ld %9ld %8ld %10s  %s\n", p.integrator.c_str(), setting, p.finalError,
                    p.maxRelEnergyDrift, 1e3 * p.cpuSeconds, p.rhsEvaluations, p.steps, p.rejectedSteps, step, note.c_str());
    }
    std::printf("\nwhole analysis: %.2f s CPU\n", r.cpuSeconds);
}

}  // namespace

int accuracyCommand(const Args& args) {
    const Options options(args, {"integrators", "tolerances", "steps", "duration", "repeats", "reference-tol", "out", "csv"});
    if (options.positional().size() != 1) throw UsageError(usageLine("accuracy"));
    Scene scene = loadSceneReportingWarnings(options.positional()[0]);
    WorkPrecisionSettings settings;
    if (options.has("integrators")) settings.integrators = parseNames(options.text("integrators"));
    if (options.has("tolerances")) settings.tolerances = parseSettings("tolerances", options.text("tolerances"));
    if (options.has("steps")) settings.steps = parseSettings("steps", options.text("steps"));
    settings.duration = options.number("duration", scene.simulation.duration);
    settings.repeats = static_cast<int>(options.number("repeats", settings.repeats));
    settings.referenceTolerance = options.number("reference-tol", 0.0);
    if (!(settings.duration > 0)) throw UsageError(UsageId::MustBePositive, "duration");
    if (settings.repeats < 1) throw UsageError(UsageId::MustBeAtLeast, "repeats", 1);
    const std::string plot = options.text("out");
    if (!plot.empty() && !plot.ends_with(".svg") && !plot.ends_with(".png")) throw UsageError(UsageId::PlotFileType, plot);
    requireValidSceneFrom(scene, options.positional()[0]);

    const bool tty = ::isatty(STDERR_FILENO);
    const present::Language language = presentation().language;
    const WorkPrecisionResult result = runWorkPrecision(scene, settings, [&](double f, const Message& what) {
        if (tty) std::fprintf(stderr, "\r%3d%% %s", static_cast<int>(100 * f), fitted(present::messageText(what, language), 40).c_str());
    });
    if (tty) std::fprintf(stderr, "\r%*s\r", 50, "");
    printTable(result);
    if (result.status == SimulationStatus::Failed) {
        std::fprintf(stderr, "%s%s\n", present::messageText(MessageId::ErrorLine, language).c_str(),
                     present::messageText(result.message, language).c_str());
        return 3;
    }
    if (options.has("csv"))
        saveFileAtomically(
            options.text("csv"), [&](std::ostream& out) { writeCsv(result, out); }, Backup::None);
    if (!plot.empty()) {
        saveAccuracyPlot(result, plot);
        std::fprintf(stderr, "plot written to %s\n", plot.c_str());
    }
    return 0;
}

}  // namespace ll::cli
