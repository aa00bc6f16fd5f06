#include "ui/window/main_window.hpp"

#include <algorithm>

#include <QAction>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileInfo>
#include <QKeyEvent>
#include <QLabel>
#include <QMenuBar>
#include <QMimeData>
#include <QPushButton>
#include <QSettings>
#include <QSplitter>
#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>
#include <QToolBar>
#include <QVBoxLayout>

#include "ui/window/autosave.hpp"
#include "ui/window/derivation_panel.hpp"
#include "ui/window/derivation_view.hpp"
#include "ui/window/dh_step_link.hpp"
#include "ui/window/dh_step_page.hpp"
#include "ui/window/dh_step_panel.hpp"
#include "ui/document/shown_derivation.hpp"
#include "core/pipeline/pose_results.hpp"
#include "ui/window/edit_frame.hpp"
#include "ui/window/entry_linking.hpp"
#include "ui/window/entry_list.hpp"
#include "ui/window/exercise_mode.hpp"
#include "ui/window/exercise_panel.hpp"
#include "ui/window/export_actions.hpp"
#include "ui/window/ghost_run.hpp"
#include "ui/window/language_menu.hpp"
#include "ui/window/lesson_mode.hpp"
#include "ui/window/model_editor.hpp"
#include "ui/window/playback_bar.hpp"
#include "ui/window/presentation_mode.hpp"
#include "ui/window/relabel.hpp"
#include "ui/window/properties_panel.hpp"
#include "ui/window/scene_files.hpp"
#include "ui/window/scene_view.hpp"
#include "ui/window/teach_mode.hpp"
#include "ui/window/teach_panel.hpp"
#include "ui/window/torque_pane.hpp"
#include "ui/window/control_tuning.hpp"
#include "ui/window/tracking_pane.hpp"
#include "ui/window/trajectory_chart.hpp"
#include "ui/window/view_bar.hpp"
#include "ui/window/view_state.hpp"
#include "ui/window/work_precision_pane.hpp"

// Q_INIT_RESOURCE must stand outside any namespace.
static void initExampleResources() { Q_INIT_RESOURCE(examples); }

namespace ll::ui {

namespace {
constexpr double kTrailSeconds = 2.0;
}

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    initExampleResources();
    setAcceptDrops(true);
    resize(1280, 800);
    relabel_ = new Relabel(this);
    parts_.window = this;
    parts_.editor = new ModelEditor(doc_, this);
    buildCentre();
    buildDocks();
    buildFeatures();
    buildMenus();
    status_ = new QLabel(this);
    statusBar()->addWidget(status_, 1);
    connectDocument();
    updateTitle();
}

MainWindow::~MainWindow() {
    // Features, then widgets and models, then (as members) the document they read; nothing
    // signals while they go (a slot would meet a feature or widget already gone).
    for (QObject* o : findChildren<QObject*>()) o->blockSignals(true);
    doc_.blockSignals(true), doc_.undoStack()->blockSignals(true);
    exercise_.reset();
    ghost_.reset();
    teachMode_.reset();
    language_.reset();
    presentationMode_.reset();
    dhStepLink_.reset();
    linking_.reset();
    exports_.reset();
    autosave_.reset();
    files_.reset();
    qDeleteAll(findChildren<QWidget*>(QString(), Qt::FindDirectChildrenOnly));
    qDeleteAll(findChildren<QAbstractItemModel*>(QString(), Qt::FindDirectChildrenOnly));
}

// ---------------------------------------------------------------- building

void MainWindow::buildCentre() {
    auto* centre = new QWidget(this);
    auto* layout = new QVBoxLayout(centre);
    layout->setContentsMargins(0, 0, 0, 0);
    SceneView* view = parts_.view = new SceneView(centre);
    auto* bar = new ViewBar(view, centre);
    parts_.playback = new PlaybackBar(centre);
    // The picked entry's value now, what feeds it; or how to pick one (ui/window/entry_linking).
    // Three lines, always: a readout that grew or shrank with its text would resize the 3D
    // view under the animation (and repaint the window ahead of an edit's result).
    QLabel* readout = parts_.readout = new QLabel(centre);
    readout->setObjectName("entry-readout");
    readout->setTextFormat(Qt::RichText);
    readout->setWordWrap(true);
    readout->setContentsMargins(6, 2, 6, 2);
    readout->setFixedHeight(3 * readout->fontMetrics().lineSpacing() + 6);
    layout->addWidget(bar);
    layout->addWidget(view, 1);
    layout->addWidget(readout);
    layout->addWidget(parts_.playback);
    setCentralWidget(centre);
}

void MainWindow::buildDocks() {
    parts_.modelDock = new QDockWidget(this);
    (*relabel_)([dock = parts_.modelDock] { dock->setWindowTitle(tr("Model")); });
    parts_.modelDock->setObjectName("model");
    parts_.modelDock->setWidget(parts_.editor);
    connect(parts_.modelDock, &QDockWidget::visibilityChanged, parts_.editor, &ModelEditor::refreshJson);
    addDockWidget(Qt::LeftDockWidgetArea, parts_.modelDock);

    // The derivation typeset, as text (Previous/Next) and its entries; the renderings follow each other.
    QDockWidget* derivationDock = parts_.derivationDock = new QDockWidget(this);
    (*relabel_)([derivationDock] { derivationDock->setWindowTitle(tr("Derivation")); });
    derivationDock->setObjectName("derivation");
    auto* textPage = new QWidget(derivationDock);
    auto* textLayout = new QVBoxLayout(textPage);
    textLayout->setContentsMargins(2, 2, 2, 2);
    DerivationPanel* derivation = parts_.derivation = new DerivationPanel(textPage);
    auto* stepBar = new QHBoxLayout;
    auto* prev = new QPushButton(textPage);
    auto* next = new QPushButton(textPage);
    auto* stepLabel = new QLabel(textPage);
    (*relabel_)([prev, next] {
        prev->setText(tr("◀ Previous step"));
        next->setText(tr("Next step ▶"));
    });
    connect(prev, &QPushButton::clicked, derivation, &DerivationPanel::previousStep);
    connect(next, &QPushButton::clicked, derivation, &DerivationPanel::nextStep);
    const auto showStep = [derivation, stepLabel] {
        const int s = derivation->step();
        const std::vector<int>& listed = derivation->steps();  // this derivation's own steps
        const auto at = std::find(listed.begin(), listed.end(), s);
        stepLabel->setText(tr("step %1 (%2 of %3)").arg(s).arg(at - listed.begin() + 1).arg(listed.size()));
    };
    connect(derivation, &DerivationPanel::stepChanged, stepLabel, showStep);
    (*relabel_)(showStep);
    for (QWidget* w : std::initializer_list<QWidget*>{prev, stepLabel, next}) stepBar->addWidget(w);
    textLayout->addLayout(stepBar);
    textLayout->addWidget(derivation, 1);
    DerivationView* typeset = parts_.typeset = new DerivationView(derivationDock);
    connect(derivation, &DerivationPanel::stepChanged, typeset, [typeset](int s) {
        if (typeset->step() != s && typeset->step() != poseStepNumber) typeset->showStep(s);
    });
    connect(typeset, &DerivationView::stepChanged, derivation, [derivation](int s) {
        if (s != poseStepNumber && derivation->step() != s) derivation->showStep(s);  // the pose is typeset only
    });
    parts_.derivationTabs = new QTabWidget(derivationDock);
    parts_.derivationTabs->addTab(typeset, QString());
    parts_.derivationTabs->addTab(textPage, QString());
    parts_.derivationTabs->addTab(new EntryList(selection_, parts_.derivationTabs), QString());
    parts_.derivationTabs->addTab(parts_.exercise = new ExercisePanel(parts_.derivationTabs), QString());
    (*relabel_)([tabs = parts_.derivationTabs] {
        tabs->setTabText(0, tr("Typeset"));
        tabs->setTabText(1, tr("Text"));
        tabs->setTabText(2, tr("Entries"));
        tabs->setTabText(3, tr("Exercise"));
    });
    derivationDock->setWidget(parts_.derivationTabs);
    addDockWidget(Qt::RightDockWidgetArea, derivationDock);

    QDockWidget* plotDock = parts_.plotDock = new QDockWidget(this);
    (*relabel_)([plotDock] { plotDock->setWindowTitle(tr("Plots")); });
    plotDock->setObjectName("plots");
    QTabWidget* tabs = parts_.plotTabs = new QTabWidget(plotDock);
    // The energy plot, and beside it the picked entry over the run (same time cursor).
    auto* energyPage = new QSplitter(Qt::Horizontal, tabs);
    parts_.energyPage = energyPage;
    parts_.energy = new TrajectoryChart(TrajectoryChart::Kind::Energy, energyPage);
    parts_.entryChart = new TrajectoryChart(TrajectoryChart::Kind::Curves, energyPage);
    parts_.entryChart->setObjectName("entry-chart");
    parts_.entryChart->hide();
    energyPage->addWidget(parts_.energy);
    energyPage->addWidget(parts_.entryChart);
    parts_.joints = new TrajectoryChart(TrajectoryChart::Kind::Joints, tabs);
    parts_.teach = new TeachPanel(tabs);
    parts_.torques = new TorquePane(tabs);
    parts_.tracking = new TrackingPane(tabs);
    parts_.properties = new PropertiesPanel(tabs);
    parts_.workPrecision = new WorkPrecisionPane(tabs);
    parts_.dhPage = new DhStepPage(tabs);
    parts_.dhSteps = parts_.dhPage->rows();
    parts_.dhAxes = parts_.dhPage->axes();
    for (QWidget* page : std::initializer_list<QWidget*>{energyPage, parts_.joints, parts_.teach, parts_.torques, parts_.properties,
                                                         parts_.workPrecision, parts_.dhPage, parts_.tracking})
        tabs->addTab(page, QString());
    (*relabel_)([tabs] {
        int i = 0;
        for (const QString& title : {tr("Energy"), tr("Joints q, dq/dt"), tr("Teach"), tr("Torques"), tr("Properties"),
                                     tr("Work–precision"), tr("DH step-through"), tr("Tracking")})
            tabs->setTabText(i++, title);
    });
    plotDock->setWidget(tabs);
    addDockWidget(Qt::BottomDockWidgetArea, plotDock);
    resizeDocks({parts_.modelDock, derivationDock}, {360, 440}, Qt::Horizontal);
    resizeDocks({plotDock}, {230}, Qt::Vertical);
}

void MainWindow::buildFeatures() {
    files_ = std::make_unique<SceneFiles>(doc_, derive_, *this);
    autosave_ = std::make_unique<Autosave>(doc_, *this);
    exports_ = std::make_unique<ExportActions>(doc_, shown_, parts_);
    linking_ = std::make_unique<EntryLinking>(selection_, shown_, parts_);
    dhStepLink_ = std::make_unique<DhStepLink>(parts_);
    connect(dhStepLink_.get(), &DhStepLink::homeReleased, this, [this] { showTime(parts_.playback->time()); });
    connect(parts_.view, &SceneView::meshesNotRead, this, [this](const QStringList& failures) {
        statusBar()->showMessage(tr("Meshes not read, so the DH drawing is shown: %1").arg(failures.join("; ")), 20000);
    });
    teachMode_ = std::make_unique<TeachMode>(doc_, selection_, *dhStepLink_, parts_);
    presentationMode_ = std::make_unique<PresentationMode>(parts_);
    language_ = std::make_unique<LanguageMenu>(*this);
    ghost_ = std::make_unique<GhostRun>(doc_, parts_);
    tuning_ = std::make_unique<ControlTuning>(doc_, parts_);
    exercise_ = std::make_unique<ExerciseMode>(doc_, selection_, *linking_, shown_, parts_, *parts_.exercise);
    views_ = new ViewState(*this, parts_);  // children: gone after the features they read
    lessons_ = new LessonMode(*this, parts_);

    autosave_->follow(*files_);
    connect(files_.get(), &SceneFiles::opened, this, [this] {
        parts_.editor->showTabForOpenedScene();
        parts_.playback->setTime(0);
        updateTitle();
    });
    connect(files_.get(), &SceneFiles::saved, this, &MainWindow::updateTitle);
    const auto showAgain = [this] {
        if (derivedAsDerived_) showDerivation(derivedAsDerived_);
    };
    connect(language_.get(), &LanguageMenu::changed, this, [this, showAgain] {
        parts_.editor->documentChanged(language_->current().language);  // the checks in the new language
        showAgain();
    });
    connect(exercise_.get(), &ExerciseMode::hiddenChanged, this, showAgain);  // other answers hidden
    connect(ghost_.get(), &GhostRun::shown, this, [this] { showTime(parts_.playback->time()); });

    // The 3D view: a joint pointed at selects its DH row; a row chosen lights its joint.
    connect(parts_.view, &SceneView::jointHovered, this, [this](int joint) {
        parts_.editor->selectDhRow(joint);
        parts_.view->highlightJoint(joint);
    });
    connect(parts_.editor, &ModelEditor::jointHighlighted, parts_.view, &SceneView::highlightJoint);
    // Time: the playback bar drives every view; a click on a plot moves it there.
    connect(parts_.playback, &PlaybackBar::timeChanged, this, &MainWindow::showTime);
    const auto scrub = [this](double t) {
        parts_.playback->pause();
        parts_.playback->setTime(t);
    };
    for (TrajectoryChart* chart : {parts_.energy, parts_.joints, parts_.entryChart})
        connect(chart, &TrajectoryChart::timePicked, parts_.playback, scrub);
    connect(parts_.torques, &TorquePane::timePicked, parts_.playback, scrub);
    connect(parts_.properties, &PropertiesPanel::timePicked, parts_.playback, scrub);
    connect(parts_.plotTabs, &QTabWidget::currentChanged, this, &MainWindow::plotTabChanged);
}

void MainWindow::buildMenus() {
    // Every text is set again when the language changes (ui/window/relabel.hpp).
    const auto menu = [this](const char* title) {
        QMenu* m = menuBar()->addMenu(QString());
        (*relabel_)([m, title] { m->setTitle(tr(title)); });
        return m;
    };
    const auto labelled = [this](QAction* a, const char* text) {
        (*relabel_)([a, text] { a->setText(tr(text)); });
        return a;
    };
    QMenu* file = menu(QT_TR_NOOP("&File"));
    files_->addOpenEntries(file);
    files_->addSaveEntries(file);
    file->addSeparator();
    QMenu* exports = file->addMenu(QString());
    (*relabel_)([exports] { exports->setTitle(tr("Export")); });
    exports_->addTo(exports);
    file->addSeparator();
    labelled(file->addAction(QString(), QKeySequence::Quit, this, &QWidget::close), QT_TR_NOOP("&Quit"));

    // Undo and redo name the edit they undo ("Undo Convention: modified (Craig)").
    QMenu* edit = menu(QT_TR_NOOP("&Edit"));
    QUndoStack* stack = doc_.undoStack();
    QAction* undo = edit->addAction(QString(), QKeySequence::Undo, stack, &QUndoStack::undo);
    QAction* redo = edit->addAction(QString(), QKeySequence::Redo, stack, &QUndoStack::redo);
    const auto name = [stack, undo, redo] {
        undo->setText(stack->undoText().isEmpty() ? tr("&Undo") : tr("&Undo %1").arg(stack->undoText()));
        redo->setText(stack->redoText().isEmpty() ? tr("&Redo") : tr("&Redo %1").arg(stack->redoText()));
        undo->setEnabled(stack->canUndo());
        redo->setEnabled(stack->canRedo());
    };
    connect(stack, &QUndoStack::indexChanged, undo, name);  // undo as context: gone with the menu, before the stack
    connect(stack, &QUndoStack::cleanChanged, undo, name);
    (*relabel_)(name);

    QMenu* sim = menu(QT_TR_NOOP("&Simulation"));
    labelled(sim->addAction(QString(), parts_.playback, &PlaybackBar::togglePlay), QT_TR_NOOP("Play / pause"));
    labelled(sim->addAction(QString(), parts_.playback, &PlaybackBar::restart), QT_TR_NOOP("Restart"));
    ghost_->addTo(sim);

    QMenu* view = menu(QT_TR_NOOP("&View"));
    view->addAction(presentationMode_->toggleAction());
    labelled(view->addAction(QString(), parts_.view, &SceneView::fit), QT_TR_NOOP("Fit view"));
    views_->addTo(view);
    view->addSeparator();
    language_->addTo(view);
    lessons_->addMenu(menuBar());

    auto* tools = addToolBar(QString());
    tools->setObjectName("main");
    (*relabel_)([tools] { tools->setWindowTitle(tr("Main")); });
    labelled(tools->addAction(QString(), files_.get(), &SceneFiles::open), QT_TR_NOOP("Open"));
    labelled(tools->addAction(QString(), files_.get(), &SceneFiles::save), QT_TR_NOOP("Save"));
    tools->addAction(undo);
    tools->addAction(redo);
    tools->addSeparator();
    labelled(tools->addAction(QString(), parts_.playback, &PlaybackBar::togglePlay), QT_TR_NOOP("▶ Play"));
    labelled(tools->addAction(QString(), this, [this] { parts_.plotTabs->setCurrentWidget(parts_.teach); }), QT_TR_NOOP("Teach"));
    labelled(tools->addAction(QString(), this, [this] { presentationMode_->setOn(!presentationMode_->on()); }), QT_TR_NOOP("Present"));
    // The status line and the title follow the language too.
    (*relabel_)([this] {
        if (status_ && shown_.result && !runFailed_) status_->setText(statusText());
        updateTitle();
    });
}

// The document and the workers: an edit is checked, each valid scene re-simulated and
// re-derived, and each result shown when it arrives (one repaint per edit, EditFrame).
void MainWindow::connectDocument() {
    editFrame_ = new EditFrame(this);
    connect(&doc_, &SceneDocument::changed, editFrame_, &EditFrame::hold);
    connect(&doc_, &SceneDocument::changed, this, &MainWindow::documentChanged);
    connect(&doc_, &SceneDocument::validated, this, &MainWindow::documentChanged);
    // A derivation of the previous scene holds the GiNaC lock the check of an edit needs:
    // it stops, and derives again when the edit turns out invalid (the valid scene stays).
    connect(&doc_, &SceneDocument::changed, &derive_, &LiveDerivation::cancel);
    connect(&doc_, &SceneDocument::validated, this, [this] {
        if (doc_.hasErrors()) {
            derive_.resume();
            editFrame_->release();  // no result to wait for: the marked cell now
        }
    });
    connect(&derive_, &LiveDerivation::started, this, [this] {
        parts_.derivation->setDeriving();
        parts_.typeset->setDeriving();
    });
    connect(&derive_, &LiveDerivation::finished, this, &MainWindow::showDerivation);
    connect(&doc_, &SceneDocument::validSceneChanged, this, &MainWindow::validSceneChanged);
    connect(doc_.undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
    connect(&live_, &LiveSimulation::finished, this, &MainWindow::showResult);
    live_.setAnalysing(true);  // torques and properties of each run, after it is shown
    connect(&live_, &LiveSimulation::analysed, this, &MainWindow::showAnalysis);
}

// ---------------------------------------------------------------- document → views

void MainWindow::documentChanged() {
    parts_.editor->documentChanged(language_->current().language);
    updateTitle();
}

void MainWindow::validSceneChanged() {
    const Scene& scene = doc_.validScene();
    live_.request(scene);
    ghost_->sceneChanged(scene);
    derive_.request(scene);
    parts_.teach->setScene(scene);
    parts_.view->setMeshDirectory(doc_.path().isEmpty() ? QString() : QFileInfo(doc_.path()).absolutePath());
    dhStepLink_->sceneChanged(scene);
    teachMode_->sceneChanged();
    parts_.workPrecision->setScene(scene);
    exercise_->sceneChanged();
}

void MainWindow::showResult(std::shared_ptr<const LiveResult> result) {
    if (result->request >= live_.latestRequest()) editFrame_->release();  // painted with this result, below
    runFailed_ = !result->visual || result->simulation.trajectory.size() == 0;
    if (runFailed_) {
        status_->setText(tr("Simulation failed: %1").arg(QString::fromStdString(result->error)));
        return;
    }
    shown_.result = result;
    const Trajectory& traj = result->simulation.trajectory;
    shown_.sampler = std::make_unique<TrajectorySampler>(traj);
    q_.resize(traj.n);
    qd_.resize(traj.n);
    effectorPath_ = result->visual->endEffectorPath(traj);  // the trail's points
    const int structure = result->scene->dof();
    const QString name = QString::fromStdString(result->scene->name);
    const bool refit = structure != shownStructure_ || name != shownName_;
    shownStructure_ = structure;
    shownName_ = name;
    parts_.view->setVisualScene(result->visual, refit);
    parts_.energy->setTrajectory(traj);
    parts_.joints->setTrajectory(traj);
    selection_.setTrajectory(&traj);
    shown_.analysis.reset();  // the torques and properties of this run follow
    parts_.torques->setTorques(nullptr, result->scene);
    parts_.tracking->setControl(nullptr, result->scene, {});
    parts_.properties->setProperties(nullptr);
    linking_->runShown();
    ghost_->runShown(*result);
    parts_.playback->setRange(shown_.sampler->startTime(), shown_.sampler->endTime());
    showTime(parts_.playback->time());
    status_->setText(statusText());
    emit resultShown(result->request);
}

// The derivation as the worker made it (English, the notes' notation), shown in the
// language and notation chosen, an exercise's answers hidden.
void MainWindow::showDerivation(std::shared_ptr<const DerivationResult> derived) {
    if (exercise_->holdsDerivation() && !derived->stopped) {  // shown once the exercise knows what to hide
        derivedAsDerived_ = derived;
        return;
    }
    const auto result = shownDerivation(derived, language_->current(), exercise_->hidden());
    parts_.derivation->setDerivation(*result);
    if (result->stopped) {
        parts_.typeset->cancel();
        return;
    }
    derivedAsDerived_ = derived;
    shown_.derived = result;
    parts_.typeset->setDerivation(result->display, result->error);
    selection_.setCatalogue(result->catalogue, result->scene);
    if (shown_.sampler && selection_.catalogue() && q_.size() == selection_.catalogue()->n)
        selection_.setState(q_, qd_, parts_.playback->time());
    exercise_->derivationShown();
}

void MainWindow::showAnalysis(std::shared_ptr<const RunAnalysis> analysis) {
    if (!shown_.result || analysis->request != shown_.result->request) return;  // of a run no longer shown
    shown_.analysis = analysis;
    parts_.torques->setTorques(analysis->torques, shown_.result->scene);
    parts_.torques->setCursorTime(parts_.playback->time());
    parts_.properties->setProperties(analysis->properties);
    parts_.tracking->setControl(analysis->control, shown_.result->scene, analysis->torques ? analysis->torques->t : std::vector<double>{});
}

void MainWindow::showTime(double t) {
    if (!shown_.sampler || !shown_.result) return;
    shown_.sampler->sample(t, q_, qd_);
    if (dhStepLink_->holdsHome()) {
        dhStepLink_->showHome();  // a new run or an edit while the frames are being found
    } else if (!teachMode_->active()) {
        std::vector<Eigen::Vector3d> trail;
        if (!effectorPath_.empty()) {
            const Trajectory& tr = shown_.result->simulation.trajectory;
            const auto from = std::lower_bound(tr.t.begin(), tr.t.end(), t - kTrailSeconds) - tr.t.begin();
            const auto to = std::upper_bound(tr.t.begin(), tr.t.end(), t) - tr.t.begin();
            trail.assign(effectorPath_.begin() + from, effectorPath_.begin() + to);
        }
        parts_.view->setPose(q_, t, &trail);
        if (!trail.empty() || shown_.result->visual->endEffector >= 0) {
            // The trail ends at the current (interpolated) position of the end effector.
            trail.push_back(shown_.result->visual->endEffectorPosition());
            parts_.view->setPose(q_, t, &trail);
        }
        ghost_->showAt(t);
        dhStepLink_->poseShown(q_);
    }
    for (TrajectoryChart* chart : {parts_.energy, parts_.joints, parts_.entryChart}) chart->setCursorTime(t);
    parts_.torques->setCursorTime(t);
    parts_.tracking->setCursorTime(t);
    if (!teachMode_->active()) selection_.setState(q_, qd_, t);
}

void MainWindow::plotTabChanged(int index) {
    QTabWidget* tabs = parts_.plotTabs;
    // The work–precision plots need height to be read: their tab gives the dock ≥ 45 % of the window.
    if (tabs->widget(index) == parts_.workPrecision && !presentationMode_->on() && parts_.plotDock->height() < height() * 45 / 100)
        resizeDocks({parts_.plotDock}, {height() * 45 / 100}, Qt::Vertical);
    if (teachMode_->tabShown(index)) return;
    if (index >= 0) linking_->valueChanged();
    showTime(parts_.playback->time());
}

QString MainWindow::statusText() const {
    if (!shown_.result) return tr("simulating…");
    const SimulationStats& s = shown_.result->simulation.stats;
    const SimulationSettings& settings = shown_.result->scene->simulation;
    const bool fixed = s.dt > 0;
    const QString tolerance = fixed ? tr("dt %1 s").arg(s.dt) : tr("tol %1").arg(settings.absTol);
    const double realTime = s.cpuSeconds > 0 ? s.simulatedSeconds / s.cpuSeconds : 0;
    int warnings = 0;
    for (const Diagnostic& d : doc_.diagnostics()) warnings += d.severity == Severity::Warning;
    QString text = tr("%1 · %2 · %3 steps · |ΔE|/E %4 · %5× real time · simulated in %6 ms")
                       .arg(QString::fromStdString(s.integrator), tolerance)
                       .arg(s.steps)
                       .arg(s.maxRelEnergyError, 0, 'g', 2)
                       .arg(realTime, 0, 'f', 0)
                       .arg(shown_.result->workerSeconds * 1000, 0, 'f', 1);
    if (warnings) text += tr(" · %n warning(s)", "", warnings);
    if (doc_.hasErrors()) text += tr(" · the model has errors: showing the last valid one");
    if (!shown_.result->error.empty()) text += " · " + QString::fromStdString(shown_.result->error).trimmed();
    return text;
}

void MainWindow::showDerivationStep(int n) {
    if (n != poseStepNumber) parts_.derivation->showStep(n);
    parts_.typeset->showStep(n);
}

void MainWindow::teach(const Eigen::VectorXd& q) { teachMode_->teach(q); }

bool MainWindow::showPlotTab(const QString& name) {
    // The plots dock's tabs in the order buildDocks adds them.
    static const QStringList names{"energy", "joints", "teach", "torques", "properties", "work-precision", "dh-steps", "tracking"};
    const int at = static_cast<int>(names.indexOf(name));  // a hidden tab (Tracking without a controller) is not shown
    if (at >= 0 && parts_.plotTabs->isTabVisible(at)) parts_.plotTabs->setCurrentIndex(at);
    return at >= 0 && parts_.plotTabs->isTabVisible(at);
}

void MainWindow::showDerivationView(const QString& name) {
    parts_.derivationTabs->setCurrentIndex(name == "text" ? 1 : name == "entries" ? 2 : name == "exercise" ? 3 : 0);
}

void MainWindow::setEditHoldLimit(int milliseconds) { editFrame_->setLimit(milliseconds); }

// ---------------------------------------------------------------- the window itself

bool MainWindow::openFile(const QString& path, QStringList* errors, bool quiet) { return files_->openFile(path, errors, quiet); }

QImage MainWindow::screenshot() { return screenshotOf(*this); }

void MainWindow::setAskBeforeClosing(bool on) { files_->setAskBeforeClosing(on); }

void MainWindow::rememberLayout() {
    remembersLayout_ = true;
    QSettings settings("LagrangeLab", "LagrangeLab");
    if (const QByteArray g = settings.value("window/geometry").toByteArray(); !g.isEmpty()) restoreGeometry(g);
    if (const QByteArray s = settings.value("window/state").toByteArray(); !s.isEmpty()) restoreState(s);
}

void MainWindow::closeEvent(QCloseEvent* e) {
    if (!files_->maybeSave() || !lessons_->maybeSave()) {
        e->ignore();
        return;
    }
    if (remembersLayout_) {  // closed while presenting: the layout from before
        QSettings settings("LagrangeLab", "LagrangeLab");
        if (!presentationMode_->on()) settings.setValue("window/geometry", saveGeometry());
        settings.setValue("window/state", presentationMode_->layoutToRemember());
    }
    autosave_->discard();
    e->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* e) {
    if (e->mimeData()->hasUrls()) e->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* e) {
    const QList<QUrl> urls = e->mimeData()->urls();
    if (urls.isEmpty() || !urls.front().isLocalFile()) return;
    e->acceptProposedAction();
    // Opened once the drop is over (the drag source is not kept waiting on the check).
    const QString path = urls.front().toLocalFile();
    QTimer::singleShot(0, this, [this, path] {
        if (files_->maybeSave()) openFile(path);
    });
}

void MainWindow::keyPressEvent(QKeyEvent* e) {
    switch (e->key()) {
        case Qt::Key_Space: parts_.playback->togglePlay(); return;
        case Qt::Key_Right: parts_.derivation->nextStep(); return;
        case Qt::Key_Left: parts_.derivation->previousStep(); return;
        case Qt::Key_F: parts_.view->fit(); return;
        case Qt::Key_Plus: parts_.playback->faster(); return;
        case Qt::Key_Minus: parts_.playback->slower(); return;
        case Qt::Key_Escape: presentationMode_->setOn(false); return;
        default: QMainWindow::keyPressEvent(e);
    }
}

void MainWindow::updateTitle() {
    const QString name = doc_.path().isEmpty() ? QString::fromStdString(doc_.validScene().name) : QFileInfo(doc_.path()).fileName();
    setWindowTitle(tr("%1%2 — LagrangeLab").arg(name, doc_.isModified() ? "*" : ""));
}

}  // namespace ll::ui
