#include "ui/window/view_state.hpp"

#include <algorithm>

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>

#include "core/io/window_view.hpp"
#include "core/model/message_error.hpp"
#include "core/pipeline/pose_results.hpp"
#include "core/present/language.hpp"
#include "core/present/message_text.hpp"
#include "core/present/notation.hpp"
#include "ui/document/app_language.hpp"
#include "ui/window/derivation_panel.hpp"
#include "ui/window/derivation_view.hpp"
#include "ui/window/dh_axes_panel.hpp"
#include "ui/window/dh_step_page.hpp"
#include "ui/window/dh_step_panel.hpp"
#include "ui/window/entry_linking.hpp"
#include "ui/window/exercise_mode.hpp"
#include "ui/window/language_menu.hpp"
#include "ui/window/main_window.hpp"
#include "ui/window/playback_bar.hpp"
#include "ui/window/presentation_mode.hpp"
#include "ui/window/relabel.hpp"
#include "ui/window/scene_files.hpp"
#include "ui/window/scene_view.hpp"
#include "ui/window/teach_panel.hpp"
#include "ui/window/torque_pane.hpp"
#include "ui/window/tracking_pane.hpp"
#include "ui/window/window_parts.hpp"

namespace ll::ui {

namespace {

// The tabs as MainWindow::showPlotTab and showDerivationView name them, in their order.
const QStringList kPlotTabs{"energy", "joints", "teach", "torques", "properties", "work-precision", "dh-steps", "tracking"};
const QStringList kDerivationTabs{"typeset", "text", "entries", "exercise"};
const char* const kTrackings[] = {"error", "torque", "lyapunov", "rate"};

QString absolute(const std::string& path) {
    const QString p = QString::fromStdString(path);
    return p.startsWith(":/") ? p : QFileInfo(p).absoluteFilePath();
}

}  // namespace

ViewState::ViewState(MainWindow& window, const WindowParts& parts) : QObject(&window), window_(window), parts_(parts) {
    // Another scene opened (File → Open, or a view's own): the embedded one is no longer on screen.
    connect(&window.files(), &SceneFiles::opened, this, [this] { embedded_.clear(); });
}

WindowView ViewState::capture() const {
    MainWindow& w = window_;
    WindowView v;
    const SceneDocument& doc = w.document();
    if (!doc.path().isEmpty() && !doc.isModified()) v.scenePath = absolute(doc.path().toStdString()).toStdString();
    else v.sceneEmbedded = doc.json();
    v.language = present::languageCode(w.language().current().language);
    v.notation = present::notationName(w.language().current().notation);
    v.present = w.presentationMode().on();
    v.size = std::array<int, 2>{w.width(), w.height()};

    v.derivation.tab = kDerivationTabs.value(parts_.derivationTabs->currentIndex(), "typeset").toStdString();
    if (w.derivationView().step() >= 0) v.derivation.step = w.derivationView().step();
    v.derivation.scroll = w.derivationView().scrollFraction();
    v.derivation.zoom = w.derivationView().zoom();

    if (const CatalogueEntry* entry = w.selection().entry()) v.pick.entry = entry->id;
    else if (w.selection().link() >= 0) v.pick.link = w.selection().link() + 1;

    PlaybackBar& playback = w.playback();
    v.playback.time = playback.time();
    v.playback.playing = playback.isPlaying();
    v.playback.speed = playback.speed();
    v.playback.loop = playback.loops();

    const CameraView& camera = w.sceneView().camera();
    if (w.sceneView().visualScene() && (camera.eye - camera.centre).norm() > 0)  // none before a first run is shown
        v.camera = WindowView::Camera{camera.eye, camera.centre, camera.up, camera.fovy};
    SceneView& view = w.sceneView();
    v.show.frames = view.showFrames();
    v.show.labels = view.showLabels();
    v.show.coms = view.showComs();
    v.show.trail = view.showTrail();
    v.show.look = view.lookWanted();

    const QString tab = kPlotTabs.value(parts_.plotTabs->currentIndex(), "energy");
    v.plots.tab = tab.toStdString();
    if (w.torquePane().joint() >= 0) v.plots.joint = w.torquePane().joint() + 1;
    if (tab == "tracking") v.plots.tracking = kTrackings[static_cast<int>(w.trackingPane().show())];
    if (tab == "dh-steps") {
        WindowView::DhSteps dh;
        if (w.dhStepPage().currentWidget() == w.dhStepPage().axes()) {
            dh.mode = "axes";
            dh.index = w.dhStepPage().axes()->step() / 4;
            dh.done = w.dhStepPage().axes()->step() % 4;
        } else {
            dh.index = w.dhStepPanel().joint() + 1;
            dh.done = w.dhStepPanel().done();
            dh.dimensions = w.dhStepPanel().showsDimensions();
        }
        v.dh = dh;
    }
    if (tab == "teach") {
        const Eigen::VectorXd& q = w.teachPanel().pose();
        v.teach = std::vector<double>(q.data(), q.data() + q.size());
    }
    v.kept = view_.kept;
    return v;
}

void ViewState::restore(const WindowView& view) {
    MainWindow& w = window_;
    view_ = view;
    problems_.clear();
    restoring_ = true;
    const int generation = ++generation_;

    // What needs no result: the language (first, so the scene opens in it, as it would at
    // start), presentation mode.
    present::Presentation presentation = w.language().current();
    if (view.language) presentation.language = present::languageNamed(*view.language).value_or(presentation.language);
    if (view.notation) presentation.notation = present::notationNamed(*view.notation).value_or(presentation.notation);
    w.language().set(presentation);
    if (view.present && *view.present != w.presentationMode().on()) w.presentationMode().setOn(*view.present);
    // The scene: opened when it is not the one open (an edited scene is asked about first).
    QStringList errors;
    if (view.sceneEmbedded) {
        const std::string text = view.sceneEmbedded->dump();
        if (text != embedded_ || w.document().isModified()) {
            if (!w.files().maybeSave())
                problems_ << tr("The scene open now was kept (its changes are not saved): the view is shown on it.");
            else if (w.files().openText(text, QString::fromStdString(view.name.empty() ? "view" : view.name), &errors, true))
                embedded_ = text;
            else
                problems_ << tr("The view's own scene could not be opened; it is shown on the scene open now:") << errors;
        }
    } else if (!view.scenePath.empty() && absolute(view.scenePath) != absolute(w.document().path().toStdString())) {
        if (!w.files().maybeSave() || !w.files().openFile(absolute(view.scenePath), &errors, true))
            problems_ << tr("The scene %1 could not be opened; the view is shown on the scene open now:").arg(QString::fromStdString(view.scenePath))
                      << errors;
        else embedded_.clear();
    }
    finish(generation, 0);
}

// The scene's run and derivation are on screen, or nothing is left to come (a run that
// failed shows no result: the view is then restored without it, and says so).
bool ViewState::sceneShown() const {
    MainWindow& w = window_;
    return !w.document().validating() && !w.liveSimulation().busy() && !w.liveDerivation().busy() && !w.exercise().judging();
}

// Waits (through the event loop, never blocking it) for the scene's results, then lets the
// presentation layout settle (it takes a few passes) before the rest is set.
void ViewState::finish(int generation, int settle) {
    if (generation != generation_) return;  // a newer view is being restored
    if (!sceneShown()) settle = 0;
    if (settle < 4) {
        QTimer::singleShot(sceneShown() ? 0 : 20, this, [this, generation, settle] { finish(generation, settle + 1); });
        return;
    }
    applyShown();
    restoring_ = false;
    if (interactive_ && !problems_.isEmpty())
        QMessageBox::information(&window_, tr("The view is shown as far as it could be"), problems_.join('\n'));
    interactive_ = false;
    emit restored(problems_);
}

// Every part of the window a view decides: what it leaves out takes its default (the
// typeset derivation at its first step, nothing picked, t = 0 paused at 1× looping, every
// toggle on, the Energy tab at joint 1, the camera fitted), so a view looks the same
// whatever was shown before it. The language and notation left out stay as they are.
void ViewState::applyShown() {
    MainWindow& w = window_;
    const WindowView& v = view_;
    const int n = w.document().validScene().dof();
    if (!w.result() || w.result()->request < w.liveSimulation().latestRequest())
        problems_ << tr("The scene's simulation failed (the status line says why): the view is shown without its run.");

    w.showDerivationView(QString::fromStdString(v.derivation.tab.value_or("typeset")));
    PlaybackBar& playback = w.playback();
    playback.setSpeed(v.playback.speed.value_or(1.0));
    playback.setLoop(v.playback.loop.value_or(true));
    playback.pause();
    const double time = v.playback.time.value_or(v.playback.play ? (*v.playback.play)[0] : 0.0);
    if (time > playback.endTime() + 1e-9)
        problems_ << tr("The time %1 s is after the run's end (%2 s): the end is shown.").arg(time).arg(playback.endTime());
    playback.setTime(std::min(time, playback.endTime()));

    w.selection().clear();
    if (v.pick.entry && !w.linking().selectEntry(QString::fromStdString(*v.pick.entry)))
        problems_ << tr("The derivation has no entry %1 any more: nothing is picked.").arg(QString::fromStdString(*v.pick.entry));
    if (v.pick.link) {
        if (*v.pick.link <= n) w.linking().pickLink(*v.pick.link - 1);
        else problems_ << tr("The scene has no link %1 (it has %2): no link is picked.").arg(*v.pick.link).arg(n);
    }
    applyPlots();

    // The step after the tabs (the teach pose shows its results as step 10).
    const std::vector<int>& steps = w.derivationPanel().steps();
    const int step = v.derivation.step.value_or(steps.empty() ? 0 : steps.front());
    const bool listed = std::find(steps.begin(), steps.end(), step) != steps.end() || (step == poseStepNumber && v.teach);
    if (listed) w.showDerivationStep(step);
    else if (!steps.empty()) {
        problems_ << tr("The derivation has no step %1 (its steps: %2 to %3): its first step is shown.").arg(step).arg(steps.front()).arg(steps.back());
        w.showDerivationStep(steps.front());
    }
    w.derivationView().setZoom(v.derivation.zoom.value_or(w.presentationMode().on() ? 1.6 : 1.0));
    w.derivationView().setScrollFraction(v.derivation.scroll.value_or(0.0));

    SceneView& view = w.sceneView();
    view.setShowFrames(v.show.frames.value_or(true));
    view.setShowLabels(v.show.labels.value_or(true));
    view.setShowComs(v.show.coms.value_or(true));
    view.setShowTrail(v.show.trail.value_or(true));
    view.setShowLook(v.show.look.value_or(true));
    if (v.camera) view.setCamera(CameraView{v.camera->eye, v.camera->target, v.camera->up, v.camera->fov});
    else view.fit();
    if (v.playback.playing.value_or(false)) playback.play();
}

void ViewState::applyPlots() {
    MainWindow& w = window_;
    const WindowView& v = view_;
    const int n = w.document().validScene().dof();
    const bool robot = !w.document().validScene().lagrangian;
    if (!w.showPlotTab(QString::fromStdString(v.plots.tab.value_or("energy")))) {
        problems_ << tr("The scene has no controller, so no Tracking tab: the Energy tab is shown.");
        w.showPlotTab("energy");
    }
    const int joint = v.plots.joint.value_or(1);
    if (joint > n) problems_ << tr("The scene has no joint %1 (it has %2): the plots show joint 1.").arg(joint).arg(n);
    w.torquePane().setJoint(joint <= n ? joint - 1 : 0);
    w.trackingPane().setJoint(joint <= n ? joint - 1 : 0);
    for (int i = 0; i < 4; ++i)
        if (v.plots.tracking.value_or("error") == kTrackings[i]) w.trackingPane().setShow(static_cast<TrackingPane::Show>(i));
    if (v.dh) {
        if (!robot) {
            problems_ << tr("A typed Lagrangian has no DH table to step through.");
        } else if (v.dh->mode == "axes") {
            w.showPlotTab("dh-steps");
            w.dhStepPage().setCurrentWidget(w.dhStepPage().axes());
            if (v.dh->index <= n) w.dhStepPage().axes()->setStep(DhConstruction::index(v.dh->index, v.dh->done));
            else problems_ << tr("The robot has no frame %1 (its frames: 0 to %2).").arg(v.dh->index).arg(n);
        } else {
            w.showPlotTab("dh-steps");
            w.dhStepPage().setCurrentWidget(w.dhStepPage().rows());
            if (v.dh->index <= n) w.dhStepPanel().setStep(v.dh->index - 1, v.dh->done);
            else problems_ << tr("The robot has no joint %1 (it has %2): the DH step-through shows joint 1.").arg(v.dh->index).arg(n);
            w.dhStepPanel().setShowDimensions(v.dh->dimensions);
        }
    }
    if (v.teach) {
        if (static_cast<int>(v.teach->size()) == n) w.teach(Eigen::Map<const Eigen::VectorXd>(v.teach->data(), n));
        else problems_ << tr("The teach pose has %1 values, the scene %2 joints: the robot is not posed.").arg(v.teach->size()).arg(n);
    }
}

void ViewState::addTo(QMenu* menu) {
    QAction* save = menu->addAction(QString(), this, &ViewState::saveAs);
    QAction* open = menu->addAction(QString(), this, &ViewState::openFile);
    (*new Relabel(menu))([save, open] {
        save->setText(tr("Save view…"));
        open->setText(tr("Open view…"));
    });
}

void ViewState::saveAs() {
    const QString path = QFileDialog::getSaveFileName(&window_, tr("Save view"), QDir::homePath() + "/view.json", tr("Views (*.json)"));
    if (path.isEmpty()) return;
    try {
        saveWindowView(capture(), path.toStdString());
        window_.statusBar()->showMessage(tr("View saved to %1").arg(path), 5000);
    } catch (const std::exception& e) {
        QMessageBox::warning(&window_, tr("Cannot save the view"), shownError(e, window_.language().current().language));
    }
}

void ViewState::openFile() {
    const QString path = QFileDialog::getOpenFileName(&window_, tr("Open view"), QDir::homePath(), tr("Views, lessons and scenes (*.json *.lesson)"));
    if (path.isEmpty()) return;
    try {
        const WindowView view = loadWindowView(path.toStdString());
        if (const std::vector<std::string> kept = view.keptPaths(); !kept.empty()) {
            std::string names;
            for (const std::string& k : kept) names += (names.empty() ? "" : ", ") + k;
            const std::string warning = present::messageText(message(MessageId::FieldsKept, names), window_.language().current().language);
            window_.statusBar()->showMessage(path + ": " + QString::fromStdString(warning), 20000);
        }
        interactive_ = true;
        restore(view);
    } catch (const std::exception& e) {
        QMessageBox::warning(&window_, tr("Cannot open the view"), shownError(e, window_.language().current().language));
    }
}

}  // namespace ll::ui
