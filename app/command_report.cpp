// `lagrangelab report SCENE --out DIR [--duration T] [--lesson LESSON]`: the lab-report bundle
// (ui/document/lab_report.hpp) in one folder: the derivation PDF, the trajectory CSV, the energy
// and joint plots as SVG, the scene file, the composite slide video and an index; with
// --lesson, the lesson's stills (`lagrangelab lesson --format png`, which needs a display) in
// DIR/lesson, shown in the index.
#include <algorithm>
#include <cstdio>
#include <optional>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <unistd.h>

#include <QProcess>

#include "app/cli_options.hpp"
#include "app/command_usage.hpp"
#include "app/commands.hpp"
#include "app/offscreen_gui.hpp"
#include "app/output_folder.hpp"
#include "app/progress_bar.hpp"
#include "app/scene_loading.hpp"
#include "core/io/data_directory.hpp"
#include "core/io/lesson_file.hpp"
#include "core/pipeline/display_derivation.hpp"
#include "core/pipeline/scene_simulation.hpp"
#include "core/present/language.hpp"
#include "core/present/localized_document.hpp"
#include "ui/document/lab_report.hpp"
#include "ui/paint/math_typesetter.hpp"

namespace ll::cli {

namespace {

// The lesson's stills as `lagrangelab lesson` makes them (a process of this program: it
// opens the window), in OUT/lesson, and a section of index.md showing them.
int addLessonStills(const Lesson& lesson, const std::string& lessonPath, const std::string& out) {
    const std::filesystem::path folder = std::filesystem::path(out) / "lesson";
    QProcess p;
    p.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    p.start(QString::fromStdString((executableDirectory() / "lagrangelab").string()),
            {"lesson", QString::fromStdString(lessonPath), "--out", QString::fromStdString(folder.string()), "--format", "png", "--size",
             "1280x720", "--lang", present::languageCode(presentation().language)});
    if (!p.waitForFinished(-1) || p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0) return p.exitCode() == 2 ? 2 : 1;
    std::vector<std::string> stills;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        if (entry.path().extension() == ".png") stills.push_back(entry.path().filename().string());
    std::sort(stills.begin(), stills.end());
    std::ofstream index(std::filesystem::path(out) / "index.md", std::ios::app);
    index << "\n## " << (lesson.title.empty() ? std::string("Lesson") : lesson.title) << "\n\n";
    for (const std::string& still : stills) {  // "03-where-b11-comes-from.png" is view 3
        const std::size_t k = std::stoul(still.substr(0, 2)) - 1;
        const WindowView* view = k < lesson.views.size() ? &lesson.views[k].view : nullptr;
        index << "![" << k + 1 << ". " << (view ? view->name : still) << "](lesson/" << still << ")\n\n";
        if (view && !view->note.empty()) index << "*" << view->note << "*\n\n";
        std::printf("%s\n", (folder / still).string().c_str());
    }
    return index ? 0 : 1;
}

}  // namespace

int reportCommand(const Args& args) {
    const Options options(args, {"out", "duration", "lesson"});
    if (options.positional().size() != 1 || !options.has("out")) throw UsageError(usageLine("report"));
    const std::string path = options.positional()[0], out = options.text("out");
    prepareOutputFolder(out);  // before the work: a folder that cannot be made or written is known now
    const std::string lessonPath = options.text("lesson");
    std::optional<Lesson> lesson;
    if (options.has("lesson")) {
        lesson = loadLesson(lessonPath);  // a lesson file that cannot be read: exit 2 now
        if (!hasDisplay()) throw UsageError(UsageId::NoDisplay);
    }
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
    if (lesson) return addLessonStills(*lesson, lessonPath, out);
    return 0;
}

}  // namespace ll::cli
