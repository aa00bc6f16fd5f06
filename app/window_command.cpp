// `lagrangelab [SCENE] [--screenshot FILE.png [--play SECONDS] [--step N] [--teach q1,...]
// [--select ENTRY] [--pick-link I] [--at T] [--tab NAME] [--joint J] [--derivation VIEW]] [--present]
// [--view FILE[#NAME]] [--save-view FILE.json]`: the desktop window (ui/window/main_window.hpp); the
// options picture any state from the command line, a saved view (ui/window/view_state.hpp) restores
// one, and --save-view writes the state the options set up as a view.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>

#include <QApplication>
#include <QBuffer>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QImage>
#include <QTimer>

#include "core/io/data_directory.hpp"
#include "core/io/json_file.hpp"
#include "core/io/lesson_file.hpp"
#include "core/io/window_view.hpp"
#include "core/present/language.hpp"
#include "core/present/notation.hpp"
#include "core/pipeline/pose_results.hpp"
#include "core/present/message_text.hpp"
#include "app/cli_options.hpp"
#include "app/command_usage.hpp"
#include "app/commands.hpp"
#include "app/event_wait.hpp"
#include "app/output_file.hpp"
#include "app/settled_screenshot.hpp"
#include "ui/window/scene_files.hpp"
#include "app/offscreen_gui.hpp"
#include "app/pixel_size.hpp"
#include "core/io/atomic_file.hpp"
#include "ui/window/exercise_mode.hpp"
#include "ui/window/main_window.hpp"
#include "ui/window/language_menu.hpp"
#include "ui/window/entry_linking.hpp"
#include "ui/window/presentation_mode.hpp"
#include "ui/window/autosave.hpp"
#include "ui/window/playback_bar.hpp"
#include "ui/document/app_language.hpp"
#include "ui/window/dh_step_panel.hpp"
#include "ui/window/scene_view.hpp"
#include "ui/window/dh_axes_panel.hpp"
#include "ui/window/dh_step_page.hpp"
#include "ui/window/torque_pane.hpp"
#include "ui/window/tracking_pane.hpp"
#include "ui/window/work_precision_pane.hpp"
#include "ui/window/view_state.hpp"
#include "ui/window/lesson_mode.hpp"

namespace ll::cli {

namespace {

// The "format" a JSON file declares ("lagrangelab-lesson/1"); empty when it declares none
// or is no JSON (the scene loader then says what is wrong with it).
std::string fileFormat(const std::string& path) {
    try {
        const scene_json::Json root = readJsonFile(path);
        return root.contains("format") && root["format"].is_string() ? root["format"].get<std::string>() : std::string();
    } catch (const std::exception&) {
        return {};
    }
}

}  // namespace

int windowCommand(const Args& args, const std::chrono::steady_clock::time_point& processStart) {
    const Options options(args,
                          {"screenshot", "play", "step", "teach", "size", "first-frame", "select", "pick-link", "at", "tab", "joint",
                           "derivation", "present", "dh-step", "dh-dimensions", "dh-from-axes", "tracking", "view", "save-view"},
                          {"first-frame", "present", "dh-dimensions"});
    if (options.positional().size() > 1) throw UsageError(UsageId::WindowTakesOneScene, options.positional().size());
    // A saved view: its scene, size, language and state (the other options override them).
    std::optional<WindowView> view;
    // A file opened (a double click): a lesson opens at its first view, its views in the
    // Lesson dock; a view file as --view; anything else is a scene.
    const std::string opened = options.positional().empty() ? std::string() : options.positional()[0];
    const std::string format = opened.ends_with(".urdf") ? std::string() : fileFormat(opened);
    const std::string lesson = format == kLessonFormat ? opened : std::string();
    int lessonStart = 0;  // the lesson's first view that can be read (an empty or broken lesson opens too)
    if (options.has("view") && !options.positional().empty()) throw UsageError(UsageId::ViewAndScene, options.text("view"));
    if (!lesson.empty() && !options.has("view")) {
        const Lesson read = loadLesson(lesson);
        while (lessonStart < int(read.views.size()) && !read.views[std::size_t(lessonStart)].problems.empty()) ++lessonStart;
        view = lessonStart < int(read.views.size()) ? read.views[std::size_t(lessonStart)].view : WindowView{};
    } else if (options.has("view") || format == kViewFormat) {
        view = loadWindowView(options.has("view") ? options.text("view") : opened);
        for (const std::string& kept : view->keptPaths())
            std::cerr << present::messageText(MessageId::WarningLine, presentation().language)
                      << present::messageText(message(MessageId::FieldsKept, kept), presentation().language) << '\n';
        if (languageGiven()) view->language = present::languageCode(presentation().language);
        if (notationGiven()) view->notation = present::notationName(presentation().notation);
    }
    const std::string saveView = options.text("save-view");
    if (options.has("save-view")) {
        if (QFileInfo(QString::fromStdString(saveView)).suffix().toLower() != "json") throw UsageError(UsageId::SaveViewNotJson, saveView);
        requireWritableOutputFile(saveView);
    }
    const std::string scene = view && !view->scenePath.empty() ? view->scenePath
                              : !opened.empty() && !view ? opened
                                                              : (examplesDirectory() / "double_pendulum.json").string();
    const std::string screenshot = options.text("screenshot");
    if (!screenshot.empty() && QFileInfo(QString::fromStdString(screenshot)).suffix().toLower() != "png")
        throw UsageError(UsageId::ScreenshotNotPng, screenshot);
    const double play = options.number("play", 0);
    if (play < 0 || play > 600) throw UsageError(UsageId::PlayOutOfRange, options.text("play"));
    const double step = options.number("step", -1);
    if (options.has("step") &&
        (step < 0 || step > poseStepNumber || step != std::floor(step) || (step == poseStepNumber && !options.has("teach"))))
        throw UsageError(UsageId::WindowStepOutOfRange, options.text("step"));
    const double at = options.number("at", 0);
    if (at < 0) throw UsageError(UsageId::AtNegative, options.text("at"));
    const std::string tab = options.text("tab");
    static const char* const tabs[] = {"energy", "joints", "teach", "torques", "properties", "work-precision", "dh-steps", "tracking"};
    if (options.has("tab") && std::find(std::begin(tabs), std::end(tabs), tab) == std::end(tabs))
        throw UsageError(UsageId::ExpectedOneOf, "tab", "energy, joints, teach, torques, properties, work-precision, dh-steps", "tracking",
                         tab);
    // --tracking: what the Tracking tab shows (a controlled robot's)
    const std::string tracking = options.text("tracking", "error");
    static const char* const trackings[] = {"error", "torque", "lyapunov", "rate"};
    const auto trackingAt = std::find(std::begin(trackings), std::end(trackings), tracking);
    if (trackingAt == std::end(trackings)) throw UsageError(UsageId::ExpectedOneOf, "tracking", "error, torque, lyapunov", "rate", tracking);
    const std::string derivationView = options.text("derivation", "typeset");
    if (derivationView != "typeset" && derivationView != "text" && derivationView != "entries" && derivationView != "exercise")
        throw UsageError(UsageId::ExpectedOneOf, "derivation", "typeset, text, entries", "exercise", derivationView);
    // The window's size; it is never made smaller than its layout's minimum.
    const std::string defaultSize =
        view && view->size ? std::to_string((*view->size)[0]) + "x" + std::to_string((*view->size)[1]) : std::string("1280x800");
    const PixelSize size = parsePixelSize(options.text("size", defaultSize));
    if (!hasDisplay()) throw UsageError(UsageId::NoDisplay);

    static int argc = 1;
    static char name[] = "lagrangelab";
    static char* argv[] = {name, nullptr};
    providePrivateRuntimeDirectory();  // no "XDG_RUNTIME_DIR not set" line from Qt
    QApplication app(argc, argv);
    QApplication::setApplicationName("LagrangeLab");
    const present::Language language = ui::startLanguage(languageGiven() ? std::optional(presentation().language) : std::nullopt);
    if (!ui::installLanguage(language)) std::cerr << "warning: the Danish catalogue could not be loaded; the window stays English\n";
    ui::MainWindow window;
    window.language().set({language, notationGiven() ? presentation().notation : ui::rememberedNotation()});
    QStringList errors;
    const QString sceneFile = QString::fromStdString(scene);  // a URDF robot is imported (File → Import URDF…)
    const bool loaded = view && view->sceneEmbedded ? window.files().openText(view->sceneEmbedded->dump(), "view", &errors, true)
                        : sceneFile.endsWith(".urdf") ? window.files().importUrdf(sceneFile, &errors, true)
                                                      : window.openFile(sceneFile, &errors, true);
    if (!loaded) {
        const std::string error = present::messageText(MessageId::ErrorLine, language);
        for (const QString& e : errors) std::cerr << error << e.toStdString() << '\n';
        return 2;
    }
    window.resize(size.width, size.height);
    const bool scripted = !screenshot.empty() || options.has("first-frame") || options.has("save-view");
    if (scripted) window.setAskBeforeClosing(false);
    if (!scripted && !options.has("size") && !view) window.rememberLayout();
    window.show();
    if (!scripted) window.autosave().offer();
    // What of the view could not be restored, as warnings.
    QObject::connect(&window.views(), &ui::ViewState::restored, &window, [](const QStringList& problems) {
        for (const QString& p : problems)
            std::cerr << present::messageText(MessageId::WarningLine, presentation().language) << p.toStdString() << '\n';
    });
    if (!lesson.empty()) window.lessons().open(QString::fromStdString(lesson));
    if (view && options.has("present")) view->present = true;
    // A lesson opens at its first view (presented with --present), selected in its dock.
    const auto restoreView = [&] {
        if (lesson.empty() || options.has("view")) window.views().restore(*view);
        else if (options.has("present") && !scripted) window.lessons().present(lessonStart);
        else if (lessonStart < int(window.lessons().lesson().views.size())) window.lessons().go(lessonStart);
        else window.views().restore(*view);  // no view to go to: the lesson's dock beside the default scene
    };
    if (view && !scripted) restoreView();
    if (options.has("present")) {
        // A scripted picture presents in a window of --size (the projector's pixels), the
        // window full screen otherwise.
        if (scripted || options.has("size")) window.presentationMode().setSize(QSize(size.width, size.height));
        window.presentationMode().setOn(true);
    }

    if (options.has("first-frame")) {
        // Start to the first drawn frame of the simulated scene (benchmarks).
        const long before = window.sceneView().framesDrawn();
        if (!waitFor([&] { return window.result() && window.sceneView().framesDrawn() > before; }, 60)) return 1;
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - processStart).count();
        std::printf("first frame after %.1f ms\n", ms);
        return 0;
    }
    if (!scripted) {
        if (!view) window.playback().play();
        return app.exec();
    }

    // Scripted: wait for the simulation and the derivation, then play, pose or step.
    if (!waitFor([&] { return window.result() && !window.liveDerivation().busy(); }, 120)) {
        std::cerr << "error: " << scene << ": the simulation or derivation did not finish in 120 s\n";
        return 1;
    }
    if (view) {
        restoreView();
        if (!waitFor([&] { return !window.views().restoring(); }, 120)) {
            std::cerr << "error: " << (lesson.empty() ? options.text("view", opened) : lesson) << ": the view was not restored in 120 s\n";
            return 1;
        }
    }
    const int n = window.document().validScene().dof();
    if (options.has("select") && !window.linking().selectEntry(QString::fromStdString(options.text("select"))))
        throw UsageError(UsageId::NoSuchEntry, scene, options.text("select"));
    if (options.has("pick-link")) {
        const double link = options.number("pick-link", 0);
        if (link < 1 || link > n || link != std::floor(link)) throw UsageError(UsageId::NotALink, options.text("pick-link"), n);
        window.linking().pickLink(static_cast<int>(link) - 1);
    }
    if (options.has("at")) {
        const double end = window.playback().endTime();
        if (at > end + 1e-9) throw UsageError(UsageId::AtAfterEnd, options.text("at"), std::to_string(end));
        window.playback().pause();
        window.playback().setTime(at);
    }
    if (options.has("tab") && !window.showPlotTab(QString::fromStdString(tab))) throw UsageError(UsageId::TrackingNeedsControl, "tab", scene);
    if (options.has("joint")) {
        const double joint = options.number("joint", 1);
        if (joint < 1 || joint > n || joint != std::floor(joint)) throw UsageError(UsageId::NotAJoint, options.text("joint"), n);
        window.torquePane().setJoint(static_cast<int>(joint) - 1);
        window.trackingPane().setJoint(static_cast<int>(joint) - 1);
    }
    if (options.has("derivation") || !view) window.showDerivationView(QString::fromStdString(derivationView));
    // an exercise: its key made and the answers the scene holds judged (what the tab shows)
    if (!waitFor([&] { return !window.exercise().judging(); }, 120)) {
        std::cerr << "error: " << scene << ": the exercise's answers were not judged in 120 s\n";
        return 1;
    }
    if (tab == "work-precision") {  // the picture of that tab is its plot: the sweep is run first
        window.workPrecisionPane().run();
        if (!waitFor([&] { return window.workPrecisionPane().hasResult(); }, 600)) {
            std::cerr << "error: " << scene << ": the work-precision sweep did not finish in 600 s\n";
            return 1;
        }
    }
    if ((tab == "torques" || tab == "properties" || tab == "tracking" || options.has("tracking")) && !waitFor([&] { return window.analysis() != nullptr; }, 120)) {
        std::cerr << "error: " << scene << ": the run's torques and properties did not come in 120 s\n";
        return 1;
    }
    if (options.has("tracking")) {
        if (!window.showPlotTab("tracking")) throw UsageError(UsageId::TrackingNeedsControl, "tracking", scene);
        window.trackingPane().setShow(static_cast<ui::TrackingPane::Show>(trackingAt - std::begin(trackings)));
    }
    if (options.has("teach")) {
        const Eigen::VectorXd q = options.vector("teach", window.document().validScene().dof());
        window.teach(q);
    }
    if (options.has("step")) window.showDerivationStep(static_cast<int>(step));
    // --dh-step I,K and --dh-from-axes I,K: two integers, each in its range, of a DH robot.
    const auto pairOf = [&](const char* option, int firstMin, int firstMax, UsageId id) {
        const std::string text = options.text(option);
        int first = 0, second = -1;
        char comma = 0, rest = 0;
        const bool parsed = std::sscanf(text.c_str(), "%d%c%d%c", &first, &comma, &second, &rest) == 3 && comma == ',';
        if (!parsed || window.document().validScene().lagrangian || first < firstMin || first > firstMax || second < 0 || second > 4)
            throw UsageError(id, text, n);
        window.showPlotTab("dh-steps");
        return std::pair{first, second};
    };
    if (options.has("dh-step")) {  // joint I (from 1), K of its four elementary motions done (0..4)
        const auto [joint, done] = pairOf("dh-step", 1, n, UsageId::DhStepExpected);
        window.dhStepPage().setCurrentWidget(window.dhStepPage().rows());
        window.dhStepPanel().setStep(joint - 1, done);
    }
    if (options.has("dh-from-axes")) {  // frame I (0..n) after K of its rules (z, origin, x, y)
        const auto [frame, done] = pairOf("dh-from-axes", 0, n, UsageId::DhFromAxesExpected);
        window.dhStepPage().setCurrentWidget(window.dhStepPage().axes());
        window.dhStepPage().axes()->setStep(ll::DhConstruction::index(frame, done));
    }
    if (options.has("dh-dimensions")) {  // every DH parameter drawn on the robot
        if (window.document().validScene().lagrangian) throw UsageError(UsageId::DhDimensionsNeedRobot, scene);
        window.showPlotTab("dh-steps");
        window.dhStepPage().setCurrentWidget(window.dhStepPage().rows());
        window.dhStepPanel().setShowDimensions(true);
    }
    if (play > 0) {
        window.playback().setLoop(false);
        window.playback().restart();
        window.playback().play();
        pauseFor(play);
        window.playback().pause();
    }
    if (!saveView.empty()) {
        saveWindowView(window.views().capture(), saveView);
        std::fprintf(stderr, "view written to %s\n", saveView.c_str());
        if (screenshot.empty()) return 0;
    }
    const QImage image = settledScreenshot(window);
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    image.save(&buffer, "PNG");
    saveFileAtomically(screenshot, bytes.toStdString(), Backup::None);
    std::fprintf(stderr, "screenshot %dx%d written to %s\n", image.width(), image.height(), screenshot.c_str());
    return 0;
}

}  // namespace ll::cli
