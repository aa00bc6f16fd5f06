// `lagrangelab report SCENE --out DIR [--duration T]`: the lab-report bundle
// (ui/document/lab_report.hpp) in one folder: the derivation PDF, the trajectory CSV, the energy
// and joint plots as SVG, the scene file, the composite slide video and an index.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <unistd.h>

#include "app/cli_options.hpp"
#include "app/command_usage.hpp"
#include "app/commands.hpp"
#include "app/offscreen_gui.hpp"
#include "app/output_folder.hpp"
#include "app/progress_bar.hpp"
#include "app/scene_loading.hpp"
#include "core/pipeline/display_derivation.hpp"
#include "core/pipeline/scene_simulation.hpp"
#include "core/present/localized_document.hpp"
#include "ui/document/lab_report.hpp"
#include "ui/paint/math_typesetter.hpp"

namespace ll::cli {

int reportCommand(const Args& args) {
    const Options options(args, {"out", "duration"});
    if (options.positional().size() != 1 || !options.has("out")) throw UsageError(usageLine("report"));
    const std::string path = options.positional()[0], out = options.text("out");
    prepareOutputFolder(out);  // before the work: a folder that cannot be made or written is known now
    Scene scene = loadSceneReportingWarnings(path);
    if (options.has("duration")) {
        const double duration = options.number("duration", 0);
        if (!(duration > 0 && duration <= 600)) throw UsageError(UsageId::ReportDurationOutOfRange, options.text("duration"));
        scene.simulation.duration = duration;
    }
    requireValidSceneFrom(scene, path);
    std::ifstream file(path, std::ios::binary);
    ui::LabReportInput input;
    input.sceneText.assign(std::istreambuf_iterator<char>(file), {});
    input.sceneFileName = std::filesystem::path(path).filename().string();

    const bool tty = ::isatty(STDERR_FILENO);
    ProgressBar bar(tty);
    input.simulation = simulate(scene, scene.simulation, [&](double f) { bar(0.1 * f); });
    if (input.simulation.status == SimulationStatus::Failed) {
        const UsageMessage stopped = usageMessage(UsageId::SimulationStoppedNoReport, input.simulation.message);
        std::fprintf(stderr, "%s\n", usageErrorLine(stopped, presentation().language).c_str());
        return 3;
    }
    DocumentRequest request;
    request.forPages = true;
    request.presentation = presentation();
    const DerivedDocument derived = inSceneFile(path, [&] { return deriveDisplay(scene, request); });
    input.display = present::localizedDocument(*derived.display, presentation());
    input.scene = std::move(scene);
    bar(0.3);
    const auto app = makeGuiApplication();
    if (!ui::mathFontsAvailable()) throw std::runtime_error("the Latin Modern fonts are missing: install fonts-lmodern");
    const std::vector<std::string> files = ui::writeLabReport(input, out, [&](double f) { bar(0.3 + 0.7 * f); });
    for (const std::string& f : files) std::printf("%s\n", (std::filesystem::path(out) / f).string().c_str());
    return 0;
}

}  // namespace ll::cli
