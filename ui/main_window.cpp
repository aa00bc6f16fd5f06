#include "ui/main_window.hpp"

#include "ui/app_language.hpp"
#include "core/present/diagnostic_text.hpp"
#include "ui/parameter_rename.hpp"

#include <algorithm>
#include <cmath>

#include <QAction>
#include <QActionGroup>
#include <QLayout>
#include <QBuffer>
#include <QApplication>
#include <QCheckBox>
#include <QCloseEvent>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QEventLoop>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QKeyEvent>
#include <QLabel>
#include <QListWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPlainTextEdit>
#include <QProgressDialog>
#include <QPointer>
#include <QLocale>
#include <QProcess>
#include <QPushButton>
#include <QRegularExpression>
#include <QScreen>
#include <QSplitter>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
#include <QTableView>
#include <QThreadPool>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>
#include <QWindow>

#include "core/io/atomic_file.hpp"
#include "core/pipeline/pose_results.hpp"
#include "core/pipeline/scene_derivation.hpp"
#include "core/visual/link_colors.hpp"
#include "ui/animation_export.hpp"
#include "ui/derivation_pages.hpp"
#include "ui/derivation_panel.hpp"
#include "ui/derivation_view.hpp"
#include "ui/entry_list.hpp"
#include "ui/field_list_model.hpp"
#include "ui/joint_table_model.hpp"
#include "ui/playback_bar.hpp"
#include "ui/properties_panel.hpp"
#include "ui/scene_view.hpp"
#include "ui/teach_panel.hpp"
#include "ui/torque_pane.hpp"
#include "ui/trajectory_chart.hpp"
#include "ui/work_precision_pane.hpp"
#include "ui/dh_step_panel.hpp"
#include "ui/example_gallery.hpp"
#include "ui/lab_report.hpp"

// Q_INIT_RESOURCE must stand outside any namespace.
static void initExampleResources() { Q_INIT_RESOURCE(examples); }

namespace ll::ui {

namespace {

constexpr int kMaxRecent = 8;
constexpr double kTrailSeconds = 2.0;

QTableView* makeTable(QAbstractItemModel* model, QWidget* parent) {
    auto* table = new QTableView(parent);
    table->setModel(model);
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed | QAbstractItemView::AnyKeyPressed);
    table->setSelectionBehavior(QAbstractItemView::SelectItems);
    return table;
}

QString sceneFilter() { return QObject::tr("LagrangeLab scenes (*.lagrange *.json);;All files (*)"); }

}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    initExampleResources();
    setAcceptDrops(true);
    resize(1280, 800);
    buildEditor();
    buildCentre();
    buildDocks();
    buildMenus();
    status_ = new QLabel(this);
    statusBar()->addWidget(status_, 1);

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
        derivation_->setDeriving();
        typeset_->setDeriving();
    });
    connect(&derive_, &LiveDerivation::finished, this, &MainWindow::showDerivation);
    connect(&doc_, &SceneDocument::validSceneChanged, this, &MainWindow::validSceneChanged);
    connect(doc_.undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
    connect(&live_, &LiveSimulation::finished, this, &MainWindow::showResult);
    live_.setAnalysing(true);  // torques and properties of each run, after it is shown
    connect(&live_, &LiveSimulation::analysed, this, &MainWindow::showAnalysis);
    connect(&selection_, &EntrySelection::selectionChanged, this, &MainWindow::selectionChanged);
    connect(&selection_, &EntrySelection::valueChanged, this, &MainWindow::selectionValueChanged);
    connect(&ghostLive_, &LiveSimulation::finished, this, &MainWindow::showGhost);
    connect(playback_, &PlaybackBar::timeChanged, this, &MainWindow::showTime);
    connect(playback_, &PlaybackBar::playingChanged, this, [this](bool playing) {
        if (!playing) return;
        teaching_ = false;
        updatePoseResults();  // the pose step goes with teach mode
    });
    autosave_.setInterval(5000);
    connect(&autosave_, &QTimer::timeout, this, [this] {
        if (doc_.isModified()) writeRecovery();
    });
    autosave_.start();
    updateTitle();
}

MainWindow::~MainWindow() {
    // The views and models read the document: they go before it (members die before
    // QWidget's destructor deletes the children).
    autosave_.stop();
    qDeleteAll(findChildren<QWidget*>(QString(), Qt::FindDirectChildrenOnly));
    qDeleteAll(findChildren<QAbstractItemModel*>(QString(), Qt::FindDirectChildrenOnly));
}

// ---------------------------------------------------------------- building

void MainWindow::buildEditor() {
    joints_ = new JointTableModel(doc_, this);
    parameters_ = new FieldListModel(doc_, parameterRows, this);
    initial_ = new FieldListModel(doc_, initialStateRows, this);
    solver_ = new FieldListModel(doc_, solverRows, this);
    lagrangian_ = new FieldListModel(doc_, lagrangianRows, this);

    editorTabs_ = new QTabWidget(this);

    // DH table with the convention, degree switch and joint list buttons.
    auto* dhPage = new QWidget(editorTabs_);
    auto* dhLayout = new QVBoxLayout(dhPage);
    auto* dhBar = new QHBoxLayout;
    convention_ = new QComboBox(dhPage);
    convention_->addItem(tr("standard (Spong)"), "standard");
    convention_->addItem(tr("modified (Craig)"), "modified");
    auto* degrees = new QCheckBox(tr("angles in degrees"), dhPage);
    dhBar->addWidget(new QLabel(tr("convention"), dhPage));
    dhBar->addWidget(convention_);
    dhBar->addWidget(degrees);
    dhBar->addStretch(1);
    dhLayout->addLayout(dhBar);
    dhView_ = makeTable(joints_, dhPage);
    dhView_->setObjectName("dh-table");
    for (int c = JointTableModel::firstInertialColumn; c <= JointTableModel::lastInertialColumn; ++c) dhView_->setColumnHidden(c, true);
    dhLayout->addWidget(dhView_, 1);
    auto* rowBar = new QHBoxLayout;
    const auto currentRow = [this] { return dhView_->currentIndex().isValid() ? dhView_->currentIndex().row() : joints_->rowCount() - 1; };
    for (auto [text, action] : std::initializer_list<std::pair<QString, std::function<void()>>>{
             {tr("Add joint"), [this, currentRow] { joints_->addJoint(currentRow()); }},
             {tr("Remove"), [this, currentRow] { joints_->removeJoint(currentRow()); }},
             {tr("Move up"), [this, currentRow] { joints_->moveJoint(currentRow(), -1); }},
             {tr("Move down"), [this, currentRow] { joints_->moveJoint(currentRow(), +1); }}}) {
        auto* button = new QPushButton(text, dhPage);
        connect(button, &QPushButton::clicked, this, action);
        rowBar->addWidget(button);
    }
    rowBar->addStretch(1);
    dhLayout->addLayout(rowBar);
    connect(convention_, &QComboBox::activated, this, [this](int i) {
        doc_.setValue("/robot/convention", convention_->itemData(i).toString().toStdString(), tr("Convention: %1").arg(convention_->itemText(i)));
    });
    connect(degrees, &QCheckBox::toggled, joints_, &JointTableModel::setDegrees);
    editorTabs_->addTab(dhPage, tr("DH"));

    // Inertials with the shape helper.
    auto* inPage = new QWidget(editorTabs_);
    auto* inLayout = new QVBoxLayout(inPage);
    inertialView_ = makeTable(joints_, inPage);
    for (int c = JointTableModel::firstDhColumn; c <= JointTableModel::lastDhColumn; ++c) inertialView_->setColumnHidden(c, true);
    inLayout->addWidget(inertialView_, 1);
    auto* shapeBar = new QHBoxLayout;
    auto* shape = new QComboBox(inPage);
    shape->addItem(tr("rod (length L)"), "rod");
    shape->addItem(tr("cylinder (r, h)"), "cylinder");
    shape->addItem(tr("disc (r)"), "disc");
    shape->addItem(tr("box (x, y, z)"), "box");
    shape->addItem(tr("sphere (r)"), "sphere");
    auto* fill = new QPushButton(tr("Fill inertia from shape…"), inPage);
    connect(fill, &QPushButton::clicked, this, [this, shape] {
        const int row = inertialView_->currentIndex().isValid() ? inertialView_->currentIndex().row() : 0;
        bool ok = false;
        const QString dims = QInputDialog::getText(this, tr("Inertia from a shape"),
                                                   tr("Joint %1, %2: dimensions in metres, comma-separated (numbers or parameters)")
                                                       .arg(row + 1).arg(shape->currentText()),
                                                   QLineEdit::Normal, "", &ok);
        if (ok) joints_->fillInertiaFromShape(row, shape->currentData().toString(), dims.split(','));
    });
    shapeBar->addWidget(shape);
    shapeBar->addWidget(fill);
    shapeBar->addStretch(1);
    inLayout->addLayout(shapeBar);
    editorTabs_->addTab(inPage, tr("Inertials"));

    // Parameters with add and remove (each one undoable edit).
    auto* parameterPage = new QWidget(editorTabs_);
    auto* parameterLayout = new QVBoxLayout(parameterPage);
    parameterView_ = makeTable(parameters_, parameterPage);
    parameterLayout->addWidget(parameterView_, 1);
    auto* parameterBar = new QHBoxLayout;
    auto* addParameterButton = new QPushButton(tr("Add parameter…"), parameterPage);
    auto* removeParameterButton = new QPushButton(tr("Remove"), parameterPage);
    auto* renameParameterButton = new QPushButton(tr("Rename…"), parameterPage);
    connect(renameParameterButton, &QPushButton::clicked, this, [this] {
        const QModelIndex index = parameterView_->currentIndex();
        if (!index.isValid()) return;
        const QString from = parameters_->row(index.row()).name;
        bool ok = false;
        const QString to = QInputDialog::getText(this, tr("Rename parameter"), tr("New name of %1 (every expression using it follows):").arg(from),
                                                 QLineEdit::Normal, from, &ok);
        QString error;
        if (ok && !renameParameter(from, to, &error)) QMessageBox::warning(this, tr("Rename parameter"), error);
    });
    connect(addParameterButton, &QPushButton::clicked, this, [this] {
        bool ok = false;
        const QString name = QInputDialog::getText(this, tr("Add parameter"), tr("Name (letters, digits, _; e.g. m3, l2, k):"),
                                                   QLineEdit::Normal, "", &ok);
        if (!ok || name.isEmpty()) return;
        const QString value = QInputDialog::getText(this, tr("Add parameter"), tr("Value of %1 (a number, SI units):").arg(name),
                                                    QLineEdit::Normal, "1", &ok);
        QString error;
        if (ok && !addParameter(name, value, &error)) QMessageBox::warning(this, tr("Add parameter"), error);
    });
    connect(removeParameterButton, &QPushButton::clicked, this, [this] {
        const QModelIndex index = parameterView_->currentIndex();
        if (index.isValid()) removeParameter(parameters_->row(index.row()).name);
    });
    parameterBar->addWidget(addParameterButton);
    parameterBar->addWidget(removeParameterButton);
    parameterBar->addWidget(renameParameterButton);
    parameterBar->addStretch(1);
    parameterLayout->addLayout(parameterBar);
    editorTabs_->addTab(parameterPage, tr("Parameters"));
    editorTabs_->addTab(makeTable(initial_, editorTabs_), tr("Initial && gravity"));
    editorTabs_->addTab(makeTable(solver_, editorTabs_), tr("Solver"));
    lagrangianPage_ = makeTable(lagrangian_, editorTabs_);
    editorTabs_->addTab(lagrangianPage_, tr("Lagrangian"));

    // The whole scene as JSON (effects, bodies, anything the tables do not list).
    auto* jsonPage = new QWidget(editorTabs_);
    auto* jsonLayout = new QVBoxLayout(jsonPage);
    jsonEdit_ = new QPlainTextEdit(jsonPage);
    jsonEdit_->setObjectName("scene-json");
    jsonEdit_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    auto* apply = new QPushButton(tr("Apply (undoable)"), jsonPage);
    connect(apply, &QPushButton::clicked, this, [this] {
        try {
            doc_.replace(SceneJson::parse(jsonEdit_->toPlainText().toStdString()), tr("Edit scene JSON"));
        } catch (const std::exception& e) {
            QMessageBox::warning(this, tr("Scene JSON"), QString::fromUtf8(e.what()));
        }
    });
    jsonLayout->addWidget(jsonEdit_, 1);
    jsonLayout->addWidget(apply);
    editorTabs_->addTab(jsonPage, tr("JSON"));
    connect(editorTabs_, &QTabWidget::currentChanged, this, &MainWindow::refreshJson);

    diagnostics_ = new QListWidget(this);
    diagnostics_->setMaximumHeight(110);
    diagnostics_->setWordWrap(true);

    // Joint selection in the DH table lights up the joint in the 3D view.
    auto highlight = [this](const QModelIndex& index) {
        if (view_) view_->highlightJoint(index.isValid() ? index.row() : -1);
    };
    connect(dhView_->selectionModel(), &QItemSelectionModel::currentChanged, this, highlight);
    connect(inertialView_->selectionModel(), &QItemSelectionModel::currentChanged, this, highlight);
}

void MainWindow::buildCentre() {
    auto* centre = new QWidget(this);
    auto* layout = new QVBoxLayout(centre);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* bar = new QToolBar(centre);
    view_ = new SceneView(centre);
    bar->addAction(tr("Fit"), view_, &SceneView::fit)->setShortcut(Qt::Key_F);
    for (const char* name : {QT_TR_NOOP("front"), QT_TR_NOOP("side"), QT_TR_NOOP("top"), QT_TR_NOOP("iso")})
        bar->addAction(tr(name), this, [this, name] { view_->setStandardView(name); });
    bar->addSeparator();
    auto toggle = [&](const QString& text, bool on, auto slot) {
        QAction* a = bar->addAction(text);
        a->setCheckable(true);
        a->setChecked(on);
        connect(a, &QAction::toggled, view_, slot);
    };
    toggle(tr("frames"), true, &SceneView::setShowFrames);
    toggle(tr("labels"), true, &SceneView::setShowLabels);
    toggle(tr("COMs"), true, &SceneView::setShowComs);
    toggle(tr("trail"), true, &SceneView::setShowTrail);
    playback_ = new PlaybackBar(centre);
    // The picked entry's value now, what feeds it; or how to pick one.
    readout_ = new QLabel(centre);
    readout_->setObjectName("entry-readout");
    readout_->setTextFormat(Qt::RichText);
    readout_->setWordWrap(true);
    readout_->setContentsMargins(6, 2, 6, 2);
    readout_->setText(readoutHint());
    // Three lines, always: a readout that grew or shrank with its text would resize the 3D
    // view under the animation (and repaint the window ahead of an edit's result).
    readout_->setFixedHeight(3 * readout_->fontMetrics().lineSpacing() + 6);
    layout->addWidget(bar);
    layout->addWidget(view_, 1);
    layout->addWidget(readout_);
    layout->addWidget(playback_);
    setCentralWidget(centre);

    // A click on a link picks it: the entries it feeds are marked, its inertials row selected.
    connect(view_, &SceneView::jointClicked, this, [this](int joint) { pickLink(joint); });
    connect(view_, &SceneView::jointHovered, this, [this](int joint) {
        if (joint >= 0 && joint < joints_->rowCount()) dhView_->selectRow(joint);
        view_->highlightJoint(joint);
    });
}

void MainWindow::buildDocks() {
    modelDock_ = new QDockWidget(tr("Model"), this);
    modelDock_->setObjectName("model");
    auto* modelPane = new QWidget(modelDock_);
    auto* modelLayout = new QVBoxLayout(modelPane);
    modelLayout->setContentsMargins(2, 2, 2, 2);
    modelLayout->addWidget(editorTabs_, 1);
    modelLayout->addWidget(new QLabel(tr("Checks (errors keep the last valid model on screen):"), modelPane));
    modelLayout->addWidget(diagnostics_);
    modelDock_->setWidget(modelPane);
    connect(modelDock_, &QDockWidget::visibilityChanged, this, &MainWindow::refreshJson);
    addDockWidget(Qt::LeftDockWidgetArea, modelDock_);

    auto* derivationDock = new QDockWidget(tr("Derivation"), this);
    derivationDock->setObjectName("derivation");
    auto* dpane = new QWidget(derivationDock);
    auto* dlayout = new QVBoxLayout(dpane);
    dlayout->setContentsMargins(2, 2, 2, 2);
    derivation_ = new DerivationPanel(dpane);
    auto* stepBar = new QHBoxLayout;
    auto* prev = new QPushButton(tr("◀ Previous step"), dpane);
    auto* next = new QPushButton(tr("Next step ▶"), dpane);
    auto* stepLabel = new QLabel(dpane);
    connect(prev, &QPushButton::clicked, derivation_, &DerivationPanel::previousStep);
    connect(next, &QPushButton::clicked, derivation_, &DerivationPanel::nextStep);
    connect(derivation_, &DerivationPanel::stepChanged, stepLabel, [this, stepLabel](int s) {
        const std::vector<int>& listed = derivation_->steps();  // this derivation's own steps
        const auto at = std::find(listed.begin(), listed.end(), s);
        stepLabel->setText(tr("step %1 (%2 of %3)").arg(s).arg(at - listed.begin() + 1).arg(listed.size()));
    });
    stepBar->addWidget(prev);
    stepBar->addWidget(stepLabel);
    stepBar->addWidget(next);
    dlayout->addLayout(stepBar);
    dlayout->addWidget(derivation_, 1);
    // Two renderings of the same steps: typeset as a textbook prints it, and as plain text
    // (searchable, copyable). They follow each other's step.
    typeset_ = new DerivationView(derivationDock);
    connect(derivation_, &DerivationPanel::stepChanged, typeset_, [this](int s) {
        if (typeset_->step() != s && typeset_->step() <= 8) typeset_->showStep(s);
    });
    connect(typeset_, &DerivationView::stepChanged, derivation_, [this](int s) {
        if (s <= 8 && derivation_->step() != s) derivation_->showStep(s);  // step 9 (the pose) is typeset only
    });
    derivationTabs_ = new QTabWidget(derivationDock);
    derivationTabs_->addTab(typeset_, tr("Typeset"));
    derivationTabs_->addTab(dpane, tr("Text"));
    entryList_ = new EntryList(selection_, derivationTabs_);
    derivationTabs_->addTab(entryList_, tr("Entries"));
    derivationDock->setWidget(derivationTabs_);
    // A click on an entry in either rendering picks it everywhere.
    connect(typeset_, &DerivationView::entryPicked, this, &MainWindow::pickedInDerivation);
    connect(derivation_, &DerivationPanel::entryPicked, this, &MainWindow::pickedInDerivation);
    addDockWidget(Qt::RightDockWidgetArea, derivationDock);

    auto* plotDock = new QDockWidget(tr("Plots"), this);
    plotDock->setObjectName("plots");
    bottomTabs_ = new QTabWidget(plotDock);
    // The energy plot, and beside it the picked entry over the run (same time cursor).
    auto* energyPage = new QSplitter(Qt::Horizontal, bottomTabs_);
    energy_ = new TrajectoryChart(TrajectoryChart::Kind::Energy, energyPage);
    entryChart_ = new TrajectoryChart(TrajectoryChart::Kind::Curves, energyPage);
    entryChart_->setObjectName("entry-chart");
    entryChart_->hide();
    energyPage->addWidget(energy_);
    energyPage->addWidget(entryChart_);
    jointsChart_ = new TrajectoryChart(TrajectoryChart::Kind::Joints, bottomTabs_);
    teach_ = new TeachPanel(bottomTabs_);
    torques_ = new TorquePane(bottomTabs_);
    properties_ = new PropertiesPanel(bottomTabs_);
    workPrecision_ = new WorkPrecisionPane(bottomTabs_);
    bottomTabs_->addTab(energyPage, tr("Energy"));
    bottomTabs_->addTab(jointsChart_, tr("Joints q, dq/dt"));
    bottomTabs_->addTab(teach_, tr("Teach"));
    bottomTabs_->addTab(torques_, tr("Torques"));
    bottomTabs_->addTab(properties_, tr("Properties"));
    bottomTabs_->addTab(workPrecision_, tr("Work–precision"));
    // The DH step-through: while its tab is shown, the 3D view draws the moving frame and
    // the DH table marks the parameter being carried out.
    dhSteps_ = new DhStepPanel(bottomTabs_);
    bottomTabs_->addTab(dhSteps_, tr("DH step-through"));
    connect(dhSteps_, &DhStepPanel::stepChanged, this, [this](int joint, int done, double fraction) {
        if (bottomTabs_->currentWidget() == dhSteps_) view_->setDhStep(joint, done, fraction);
    });
    connect(dhSteps_, &DhStepPanel::parameterChanged, this, [this](int joint, DhParameter parameter) {
        if (bottomTabs_->currentWidget() != dhSteps_ || joint < 0 || joint >= joints_->rowCount()) return;
        const int column = parameter == DhParameter::A       ? JointTableModel::A
                           : parameter == DhParameter::Alpha ? JointTableModel::Alpha
                           : parameter == DhParameter::D     ? JointTableModel::D
                                                             : JointTableModel::Theta;
        dhView_->setCurrentIndex(dhView_->model()->index(joint, column));
    });
    connect(dhSteps_, &DhStepPanel::dimensionsToggled, this, [this](bool on) {
        view_->setShowDimensions(on && bottomTabs_->currentWidget() == dhSteps_);
    });
    connect(bottomTabs_, &QTabWidget::currentChanged, this, [this] {
        const bool shown = bottomTabs_->currentWidget() == dhSteps_;
        view_->setShowDimensions(shown && dhSteps_->showsDimensions());
        if (shown) {
            dhSteps_->setPose(view_->shownPose());
            dhSteps_->setStep(dhSteps_->joint(), dhSteps_->done());  // marks the table, draws the frame
        } else {
            view_->setDhStep(-1, 0, 0);
        }
    });
    plotDock->setWidget(bottomTabs_);
    addDockWidget(Qt::BottomDockWidgetArea, plotDock);
    resizeDocks({modelDock_, derivationDock}, {360, 440}, Qt::Horizontal);
    resizeDocks({plotDock}, {230}, Qt::Vertical);

    const auto scrub = [this](double t) {
        playback_->pause();
        playback_->setTime(t);
    };
    for (TrajectoryChart* chart : {energy_, jointsChart_, entryChart_}) connect(chart, &TrajectoryChart::timePicked, playback_, scrub);
    connect(torques_, &TorquePane::timePicked, playback_, scrub);
    connect(properties_, &PropertiesPanel::timePicked, playback_, scrub);
    // An entry picked in the teach panel's B(q), g(q) is the derivation's entry of that quantity.
    connect(teach_, &TeachPanel::entryPicked, this, [this](present::Quantity quantity, int row, int col) {
        if (!selection_.catalogue()) return;
        if (const CatalogueEntry* e = selection_.catalogue()->ofQuantity(quantity, row, col)) selection_.select(e->id);
    });
    connect(teach_, &TeachPanel::poseChanged, this, [this](const Eigen::VectorXd& q) {
        if (!teaching_ || !view_) return;
        showTeachPose(q);
        updatePoseResults();
    });
    connect(bottomTabs_, &QTabWidget::currentChanged, this, [this](int index) {
        // The work–precision plots need height to be read (two log–log plots and a
        // legend): their tab gives the dock at least 45 % of the window.
        if (bottomTabs_->widget(index) == workPrecision_ && !presenting_)
            if (auto* plots = findChild<QDockWidget*>("plots"); plots && plots->height() < height() * 45 / 100)
                resizeDocks({plots}, {height() * 45 / 100}, Qt::Vertical);
        teaching_ = bottomTabs_->widget(index) == teach_;
        if (!teaching_ && index >= 0) selectionValueChanged();
        updatePoseResults();
        if (teaching_) {
            playback_->pause();
            showTeachPose(teach_->pose());
        } else {
            showTime(playback_->time());
        }
    });
}

void MainWindow::buildMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&Open…"), QKeySequence::Open, this, &MainWindow::open);
    QMenu* examples = file->addMenu(tr("Examples"));
    examples->addAction(tr("Gallery…"), this, [this] {
        auto* gallery = new ExampleGallery(this);
        gallery->setAttribute(Qt::WA_DeleteOnClose);
        connect(gallery, &ExampleGallery::chosen, this, [this](const QString& path) {
            if (maybeSave()) openFile(path);
        });
        gallery->open();
    });
    examples->addSeparator();
    for (const QString& name : QDir(":/examples").entryList({"*.json"}, QDir::Files, QDir::Name))
        examples->addAction(name, this, [this, name] {
            if (maybeSave()) openFile(":/examples/" + name);
        });
    recentMenu_ = file->addMenu(tr("Recent files"));
    rebuildRecentMenu();
    file->addAction(tr("&Save"), QKeySequence::Save, this, &MainWindow::save);
    file->addAction(tr("Save &as…"), QKeySequence::SaveAs, this, &MainWindow::saveAs);
    file->addSeparator();
    QMenu* exports = file->addMenu(tr("Export"));
    exports->addAction(tr("Screenshot (PNG)…"), this, &MainWindow::exportScreenshot);
    exports->addAction(tr("Plot (PNG, SVG or CSV)…"), this, &MainWindow::exportPlot);
    exports->addAction(tr("Derivation (PDF, SVG, PNG, LaTeX or text)…"), this, &MainWindow::exportDerivation);
    exports->addAction(tr("Animation (MP4, WebM, GIF)…"), this, &MainWindow::exportAnimation);
    // One video for a slide: the 3D view, the derivation step shown and the energy plot.
    for (const QSize size : {QSize(1280, 720), QSize(1920, 1080)})
        exports->addAction(tr("Video for slides, %1×%2 (3D view, equation, energy)…").arg(size.width()).arg(size.height()), this, [this, size] {
            const QString path = QFileDialog::getSaveFileName(this, tr("Export video for slides"), "slide.mp4",
                                                              tr("MP4 (*.mp4);;WebM (*.webm);;GIF (*.gif);;PNG still (*.png)"));
            QString error;
            if (!path.isEmpty() && !exportAnimationTo(path, &error, -1, true, size))
                QMessageBox::critical(this, tr("Export video for slides"), error);
        });
    exports->addAction(tr("Lab report (PDF, CSV, SVG plots, scene, video) into a folder…"), this, [this] {
        const QString dir = QFileDialog::getExistingDirectory(this, tr("Lab report: choose or make a folder"));
        QString error;
        if (!dir.isEmpty() && !exportLabReportTo(dir, &error)) QMessageBox::critical(this, tr("Lab report"), error);
    });
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = doc_.undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = doc_.undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    edit->addAction(undo);
    edit->addAction(redo);

    QMenu* sim = menuBar()->addMenu(tr("&Simulation"));
    sim->addAction(tr("Play / pause"), playback_, &PlaybackBar::togglePlay);
    sim->addAction(tr("Restart"), playback_, &PlaybackBar::restart);
    QMenu* ghost = sim->addMenu(tr("Ghost run"));
    auto* group = new QActionGroup(this);
    for (const QString& name : {QString(), QString("euler"), QString("midpoint"), QString("rk4"), QString("symplectic_euler"), QString("dopri5 1e-3")}) {
        QAction* a = ghost->addAction(name.isEmpty() ? tr("none") : name, this, [this, name] { setGhostIntegrator(name); });
        a->setCheckable(true);
        a->setChecked(name.isEmpty());
        group->addAction(a);
    }

    // Presentation mode's keys, whichever widget has the focus (a button would take the
    // space, the step list the arrows); off otherwise, so the editors keep their keys. F
    // (fit) is the 3D view bar's shortcut, always on.
    for (auto [key, slot] : std::initializer_list<std::pair<QKeySequence, std::function<void()>>>{
             {Qt::Key_Space, [this] { playback_->togglePlay(); }},
             {Qt::Key_Right, [this] { derivation_->nextStep(); }},
             {Qt::Key_Left, [this] { derivation_->previousStep(); }},
             {Qt::Key_Plus, [this] { playback_->faster(); }},
             {Qt::Key_Minus, [this] { playback_->slower(); }},
             {Qt::Key_Escape, [this] { setPresentationMode(false); }}}) {
        auto* action = new QAction(this);
        action->setShortcut(key);
        action->setShortcutContext(Qt::WindowShortcut);
        action->setEnabled(false);
        connect(action, &QAction::triggered, this, slot);
        addAction(action);
        presentationKeys_ << action;
    }

    QMenu* view = menuBar()->addMenu(tr("&View"));
    QAction* present = view->addAction(tr("Presentation mode"), this, [this] { setPresentationMode(!presenting_); });
    present->setShortcut(Qt::Key_F11);
    addAction(present);  // F11 leaves presentation mode, where the menu bar is hidden
    view->addAction(tr("Fit view"), view_, &SceneView::fit);
    view->addSeparator();
    // The derivation's language and the textbook's letters; remembered for the next start.
    languageMenu_ = view->addMenu(tr("&Language"));
    auto* languages = new QActionGroup(languageMenu_);
    for (const auto& [code, name] : {std::pair{"da", "Dansk"}, {"en", "English"}}) {  // each language in its own name
        QAction* a = languageMenu_->addAction(QString::fromUtf8(name));
        a->setData(QString::fromLatin1(code));
        a->setCheckable(true);
        languages->addAction(a);
        connect(a, &QAction::triggered, this, [this, code = std::string(code)] {
            const present::Language language = *present::languageNamed(code);
            rememberLanguage(language);
            setPresentation({language, presentation_.notation});
            if (language != windowLanguage())
                statusBar()->showMessage(tr("The derivation is shown in the new language now; the menus and panels follow when LagrangeLab starts again."), 8000);
        });
    }
    notationMenu_ = view->addMenu(tr("&Notation"));
    auto* notations = new QActionGroup(notationMenu_);
    for (const auto& [id, label] : {std::pair{present::Notation::Notes, QT_TR_NOOP("The course notes: B q̈ + C q̇ + g = Q")},
                                    {present::Notation::Siciliano, QT_TR_NOOP("Siciliano: B q̈ + C q̇ + g = τ")},
                                    {present::Notation::Spong, QT_TR_NOOP("Spong: D q̈ + C q̇ + g = τ")},
                                    {present::Notation::Craig, QT_TR_NOOP("Craig: M Θ̈ + V + G = τ (modified DH)")}}) {
        QAction* a = notationMenu_->addAction(tr(label));
        a->setData(QString::fromLatin1(present::notationName(id)));
        a->setCheckable(true);
        notations->addAction(a);
        connect(a, &QAction::triggered, this, [this, id = id] {
            rememberNotation(id);
            setPresentation({presentation_.language, id});
        });
    }
    setPresentation(presentation_);

    auto* tools = addToolBar(tr("Main"));
    tools->setObjectName("main");
    tools->addAction(tr("Open"), this, &MainWindow::open);
    tools->addAction(tr("Save"), this, &MainWindow::save);
    tools->addAction(undo);
    tools->addAction(redo);
    tools->addSeparator();
    tools->addAction(tr("▶ Play"), playback_, &PlaybackBar::togglePlay);
    tools->addAction(tr("Teach"), this, [this] { bottomTabs_->setCurrentWidget(teach_); });
    tools->addAction(tr("Present"), this, [this] { setPresentationMode(!presenting_); });
}

// ---------------------------------------------------------------- document → views

void MainWindow::documentChanged() {
    const std::string convention = doc_.value("/robot/convention").is_string() ? doc_.value("/robot/convention").get<std::string>() : "standard";
    convention_->setCurrentIndex(convention == "modified" ? 1 : 0);
    jsonStale_ = true;
    refreshJson();
    diagnostics_->clear();
    for (const Diagnostic& d : doc_.diagnostics()) {
        QString text = QString::fromStdString(present::diagnosticText(d, presentation_.language));
        // An error on a whole joint (B singular there) right after one value was edited:
        // that value is named, the likely cause the message itself cannot know.
        const std::string& edited = doc_.lastEditedField();
        if (d.severity == Severity::Error && !edited.empty() && d.field.ends_with("]") &&
            d.field.find("robot.joints[") != std::string::npos && edited.rfind("robot.joints[", 0) == 0)
            text += "\n" + tr("hint: it happened with your edit of %1")
                               .arg(QString::fromStdString(Diagnostic{Severity::Error, edited, ""}.where()));
        auto* item = new QListWidgetItem(text, diagnostics_);
        item->setForeground(d.severity == Severity::Error ? QColor(180, 0, 0) : QColor(140, 100, 0));
    }
    if (doc_.diagnostics().empty()) new QListWidgetItem(tr("no errors, no warnings"), diagnostics_);
    updateTitle();
}

// The JSON tab's text follows the document while it is seen; hidden, it is refilled when
// shown (setPlainText and its layout cost 2–3 ms of every edit's frame for nothing).
void MainWindow::refreshJson() {
    if (!jsonStale_ || !jsonEdit_->isVisible() || jsonEdit_->hasFocus()) return;
    jsonEdit_->setPlainText(QString::fromStdString(doc_.text()));
    jsonStale_ = false;
}

void MainWindow::validSceneChanged() {
    const Scene& scene = doc_.validScene();
    live_.request(scene);
    if (!ghostIntegrator_.isEmpty()) ghostLive_.request(scene);
    derive_.request(scene);
    teach_->setScene(scene);
    dhSteps_->setRobot(scene.robot, !scene.lagrangian);
    updatePoseResults();
    workPrecision_->setScene(scene);
}

void MainWindow::showResult(std::shared_ptr<const LiveResult> result) {
    if (result->request >= live_.latestRequest()) editFrame_->release();  // painted with this result, below
    if (!result->visual || result->simulation.trajectory.size() == 0) {
        status_->setText(tr("Simulation failed: %1").arg(QString::fromStdString(result->error)));
        return;
    }
    result_ = result;
    const Trajectory& traj = result->simulation.trajectory;
    sampler_ = std::make_unique<TrajectorySampler>(traj);
    q_.resize(traj.n);
    qd_.resize(traj.n);
    // The end effector at every sample, for the trail.
    effectorPath_.clear();
    VisualScene& visual = *result->visual;
    if (visual.endEffector >= 0) {
        effectorPath_.reserve(traj.size());
        for (std::size_t k = 0; k < traj.size(); ++k) {
            visual.pose(traj.q[k], traj.t[k]);
            effectorPath_.push_back(visual.endEffectorPosition());
        }
    }
    const int structure = result->scene->dof();
    const QString name = QString::fromStdString(result->scene->name);
    const bool refit = structure != shownStructure_ || name != shownName_;
    shownStructure_ = structure;
    shownName_ = name;
    view_->setVisualScene(result->visual, refit);
    energy_->setTrajectory(traj);
    jointsChart_->setTrajectory(traj);
    selection_.setTrajectory(&traj);
    analysis_.reset();  // the torques and properties of this run follow
    torques_->setTorques(nullptr, result->scene);
    properties_->setProperties(nullptr);
    view_->setEmphasis(selection_.emphasis(visual));
    selectionChanged();
    if (ghost_ && ghost_->simulation.trajectory.size() > 0) energy_->setGhost(&ghost_->simulation.trajectory, ghostIntegrator_);
    playback_->setRange(sampler_->startTime(), sampler_->endTime());
    showTime(playback_->time());
    status_->setText(statusText());
    emit resultShown(result->request);
}

void MainWindow::showDerivation(std::shared_ptr<const DerivationResult> derived) {
    std::shared_ptr<const DerivationResult> result = derived;
    if (derived->display && (presentation_.language != present::Language::English || presentation_.notation != present::Notation::Notes)) {
        auto shown = std::make_shared<DerivationResult>(*derived);
        shown->display = present::localizedDocument(*derived->display, presentation_);
        shown->textSpans.clear();
        shown->text = QString::fromStdString(present::textDocument(*shown->display, &shown->textSpans));
        result = shown;
    }
    derivation_->setDerivation(*result);
    if (result->stopped) {
        typeset_->cancel();
        return;
    }
    derivedAsDerived_ = derived;
    derived_ = result;
    typeset_->setDerivation(result->display, result->error);
    selection_.setCatalogue(result->catalogue, result->scene);
    if (sampler_ && selection_.catalogue() && q_.size() == selection_.catalogue()->n) selection_.setState(q_, qd_, playback_->time());
}

void MainWindow::setPresentation(const present::Presentation& presentation) {
    presentation_ = presentation;
    if (languageMenu_)
        for (QAction* a : languageMenu_->actions())
            a->setChecked(a->data().toString() == QString::fromLatin1(present::languageCode(presentation.language)));
    if (notationMenu_)
        for (QAction* a : notationMenu_->actions())
            a->setChecked(a->data().toString() == QString::fromLatin1(present::notationName(presentation.notation)));
    if (derivedAsDerived_) showDerivation(derivedAsDerived_);
}

void MainWindow::showAnalysis(std::shared_ptr<const RunAnalysis> analysis) {
    if (!result_ || analysis->request != result_->request) return;  // of a run no longer shown
    analysis_ = analysis;
    torques_->setTorques(analysis->torques, result_->scene);
    torques_->setCursorTime(playback_->time());
    properties_->setProperties(analysis->properties);
}

void MainWindow::pickedInDerivation(int step, int item, int row, int col) {
    if (!selection_.catalogue()) return;
    if (step < 0) {  // the results at the teach pose: the same quantity's entry in the derivation
        const present::DisplayStep* pose = typeset_->poseResults();
        if (!pose || item < 0 || item >= static_cast<int>(pose->items.size())) return;
        if (const CatalogueEntry* e = selection_.catalogue()->ofQuantity(pose->items[static_cast<std::size_t>(item)].quantity, row, col))
            selection_.select(e->id);
        return;
    }
    if (!selection_.selectAt(step, item, row, col)) selection_.clear();
}

bool MainWindow::selectEntry(const QString& id) { return selection_.select(id.toStdString()); }

void MainWindow::pickLink(int link) {
    selection_.pickLink(link);
    if (link >= 0 && link < joints_->rowCount()) {
        editorTabs_->setCurrentIndex(1);  // Inertials
        inertialView_->selectRow(link);
        view_->highlightJoint(-1);  // the link shows in its own colour, not the selection's
    }
}

bool MainWindow::showPlotTab(const QString& name) {
    const std::pair<const char*, QWidget*> tabs[] = {{"energy", energy_->parentWidget()}, {"joints", jointsChart_},
                                                     {"teach", teach_},                  {"torques", torques_},
                                                     {"properties", properties_},        {"work-precision", workPrecision_},
                                                     {"dh-steps", dhSteps_}};
    for (const auto& [key, widget] : tabs)
        if (name == key) {
            bottomTabs_->setCurrentWidget(widget);
            return true;
        }
    return false;
}

void MainWindow::showDerivationView(const QString& name) {
    derivationTabs_->setCurrentIndex(name == "text" ? 1 : name == "entries" ? 2 : 0);
}

QString MainWindow::readoutHint() const {
    return tr("Click an entry of the derivation (b11, g2, …) or a link in the 3D view to see what feeds it and its value now.");
}

QString MainWindow::readoutText() const { return readout_->text(); }

// The pick changed: every view shows it (marks, the plot, the 3D emphasis, the readout).
void MainWindow::selectionChanged() {
    std::vector<EntryMark> marks;
    if (const CatalogueEntry* e = selection_.entry()) {
        marks.push_back({e->step, e->item, e->cell ? e->row : -1, e->cell ? e->col : -1, QColor(255, 214, 90, 150)});
        // Show it where it is: the typeset page of its step, the text at its line.
        typeset_->showDocumentStep(e->step, e->item, e->cell ? e->row : -1, e->cell ? e->col : -1);
        derivation_->showItem(e->step, e->item);
    }
    if (selection_.link() >= 0) {
        const Rgba c = linkColor(selection_.link());
        for (const CatalogueEntry* e : selection_.marked())
            marks.push_back({e->step, e->item, e->cell ? e->row : -1, e->cell ? e->col : -1,
                             QColor(int(c.r * 255), int(c.g * 255), int(c.b * 255), 60)});
    }
    typeset_->setMarks(marks);
    derivation_->setMarks(marks);
    // The teach panel tints the same entry of its B(q) or g(q).
    if (const CatalogueEntry* picked = selection_.entry(); picked && picked->row >= 0) {
        using present::Quantity;
        const Quantity q = picked->quantity == Quantity::MassMatrixEntry   ? Quantity::MassMatrix
                           : picked->quantity == Quantity::GravityEntry    ? Quantity::GravityVector
                                                                           : picked->quantity;
        teach_->matrices().setMark(q, picked->row, picked->col);
    } else if (picked && picked->quantity == present::Quantity::PotentialEnergy) {
        teach_->matrices().setMark(picked->quantity);
    } else {
        teach_->matrices().setMark(std::nullopt);
    }
    // The entry over the run, beside the energy plot.
    std::vector<double> t, values;
    selection_.series(t, values);
    const CatalogueEntry* e = selection_.entry();
    if (e && !values.empty()) {
        const QString name = QString::fromStdString(e->label);
        entryChart_->setCurves(t, {{name, QColor(200, 120, 0), Qt::SolidLine, values}},
                               e->unit.empty() ? name : QString("%1 [%2]").arg(name, QString::fromStdString(e->unit)));
        entryChart_->setCursorTime(playback_->time());
        entryChart_->show();
    } else {
        entryChart_->hide();
    }
    selectionValueChanged();
}

// A new time or pose: the value, the shares, the emphasis.
void MainWindow::selectionValueChanged() {
    if (!selection_.active()) {
        readout_->setText(readoutHint());
        if (view_->emphasis().active()) view_->setEmphasis({});
        return;
    }
    readout_->setText(selection_.readout());
    if (result_ && result_->visual) view_->setEmphasis(selection_.emphasis(*result_->visual));
}

void MainWindow::showGhost(std::shared_ptr<const LiveResult> result) {
    if (ghostIntegrator_.isEmpty() || !result->visual || result->simulation.trajectory.size() == 0) return;
    ghost_ = result;
    ghostSampler_ = std::make_unique<TrajectorySampler>(ghost_->simulation.trajectory);
    view_->setGhost(ghost_->visual);
    energy_->setGhost(&ghost_->simulation.trajectory, ghostIntegrator_);
    showTime(playback_->time());
}

void MainWindow::showTime(double t) {
    if (!sampler_ || !result_) return;
    sampler_->sample(t, q_, qd_);
    if (!teaching_) {
        std::vector<Eigen::Vector3d> trail;
        if (!effectorPath_.empty()) {
            const Trajectory& tr = result_->simulation.trajectory;
            const auto from = std::lower_bound(tr.t.begin(), tr.t.end(), t - kTrailSeconds) - tr.t.begin();
            const auto to = std::upper_bound(tr.t.begin(), tr.t.end(), t) - tr.t.begin();
            trail.assign(effectorPath_.begin() + from, effectorPath_.begin() + to);
        }
        view_->setPose(q_, t, &trail);
        if (!trail.empty() || result_->visual->endEffector >= 0) {
            // The trail ends at the current (interpolated) position of the end effector.
            trail.push_back(result_->visual->endEffectorPosition());
            view_->setPose(q_, t, &trail);
        }
        if (ghostSampler_) {
            Eigen::VectorXd gq(ghostSampler_->dof()), gqd(ghostSampler_->dof());
            ghostSampler_->sample(t, gq, gqd);
            view_->setGhostPose(gq, t);
        }
        if (bottomTabs_->currentWidget() == dhSteps_) dhSteps_->setPose(q_);
    }
    energy_->setCursorTime(t);
    jointsChart_->setCursorTime(t);
    entryChart_->setCursorTime(t);
    torques_->setCursorTime(t);
    if (!teaching_) selection_.setState(q_, qd_, t);
}

QString MainWindow::statusText() const {
    if (!result_) return tr("simulating…");
    const SimulationStats& s = result_->simulation.stats;
    const SimulationSettings& settings = result_->scene->simulation;
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
                       .arg(result_->workerSeconds * 1000, 0, 'f', 1);
    if (warnings) text += tr(" · %n warning(s)", "", warnings);
    if (doc_.hasErrors()) text += tr(" · the model has errors: showing the last valid one");
    if (!result_->error.empty()) text += " · " + QString::fromStdString(result_->error).trimmed();
    return text;
}

QStringList MainWindow::diagnosticLines() const {
    QStringList lines;
    for (int i = 0; i < diagnostics_->count(); ++i) lines << diagnostics_->item(i)->text();
    return lines;
}

void MainWindow::showDerivationStep(int n) {
    if (n <= 8) derivation_->showStep(n);
    typeset_->showStep(n);
}

// The robot at a teach pose, without the trail of the motion (which is not where it is).
void MainWindow::showTeachPose(const Eigen::VectorXd& q) {
    static const std::vector<Eigen::Vector3d> noTrail;
    view_->setPose(q, playback_->time(), &noTrail);
    if (bottomTabs_->currentWidget() == dhSteps_) dhSteps_->setPose(q);
    // The picked entry at the pose, the joints at rest (as the pose results take them).
    const Scene& scene = doc_.validScene();
    const int n = static_cast<int>(q.size());
    selection_.setState(q, scene.initial.qd.size() == n ? scene.initial.qd : Eigen::VectorXd::Zero(n), playback_->time(), true);
}

// Step 9 of the typeset derivation while teaching: B, C, g and the energies at the pose.
void MainWindow::updatePoseResults() {
    const Scene& scene = doc_.validScene();
    const int n = scene.robot.dof();
    if (!teaching_ || scene.lagrangian || n == 0 || teach_->pose().size() != n) {
        typeset_->setPoseResults(nullptr);
        return;
    }
    const Eigen::VectorXd qd = scene.initial.qd.size() == n ? scene.initial.qd : Eigen::VectorXd::Zero(n);
    typeset_->setPoseResults(std::make_shared<const present::DisplayStep>(poseResults(scene, teach_->pose(), qd)));
}

void MainWindow::teach(const Eigen::VectorXd& q) {
    bottomTabs_->setCurrentWidget(teach_);
    teach_->setPose(q);
    showTeachPose(teach_->pose());
}

void MainWindow::setGhostIntegrator(const QString& integrator) {
    ghostIntegrator_ = integrator;
    ghost_.reset();
    ghostSampler_.reset();
    view_->setGhost(nullptr);
    energy_->setGhost(nullptr, {});
    if (integrator.isEmpty()) return;
    SimulationSettings settings = doc_.validScene().simulation;
    const QStringList words = integrator.split(' ');
    settings.integrator = words[0].toStdString();
    if (words.size() > 1) settings.absTol = settings.relTol = words[1].toDouble();
    if (settings.integrator == "euler" || settings.integrator == "midpoint" || settings.integrator == "rk4" || settings.integrator == "symplectic_euler")
        settings.dt = 0.01;
    ghostLive_.setSettingsOverride(settings);
    ghostLive_.requestNow(doc_.validScene());
}

void MainWindow::setPresentationMode(bool on) {
    if (on == presenting_) return;
    if (on) {  // the layout as it is, to come back to exactly
        layoutBeforePresenting_ = saveState();
        geometryBeforePresenting_ = geometry();
    }
    presenting_ = on;
    modelDock_->setVisible(!on);
    // Nothing a projector's audience needs to read twice: the menus (F11 and the keys stay
    // live as the window's own actions), the tool bar, the status line and the pick hint.
    menuBar()->setVisible(!on);
    statusBar()->setVisible(!on);
    readout_->setVisible(!on);
    for (QToolBar* bar : findChildren<QToolBar*>(QString(), Qt::FindDirectChildrenOnly)) bar->setVisible(!on);
    QFont font = QApplication::font();
    static const double base = font.pointSizeF() > 0 ? font.pointSizeF() : 10;
    font.setPointSizeF(on ? base * 1.6 : base);
    QApplication::setFont(font);
    derivation_->setZoom(on ? 1.6 : 1.0);
    typeset_->setZoom(on ? 1.6 : 1.0);  // 24 px per em: 18 pt at 96 dpi
    typeset_->setPageOnly(on);
    derivationTabs_->tabBar()->setVisible(!on);
    bottomTabs_->tabBar()->setVisible(!on);
    // Only the energy plot is shown: the other tabs' widest page (the DH step-through's
    // matrix at 1.6×) must not set the column's width. 0 gives the pages' minimum back.
    bottomTabs_->setMinimumWidth(on ? 200 : 0);
    readout_->setFixedHeight(3 * QFontMetrics(font).lineSpacing() + 6);
    // The plots: bigger labels and lines need room, so their dock gets more height, and
    // the dock titles (which the application font does not reach) grow too.
    for (TrajectoryChart* chart : {energy_, jointsChart_}) chart->setScale(on ? 1.4 : 1.0);
    // A dock paints its title in the platform's small title font whatever the application
    // font is, so presenting docks get a label of their own as title.
    for (QDockWidget* dock : findChildren<QDockWidget*>()) {
        QWidget* old = dock->titleBarWidget();
        if (on && !old) {
            auto* title = new QLabel(dock->windowTitle(), dock);
            title->setContentsMargins(6, 2, 6, 2);
            dock->setTitleBarWidget(title);
        } else if (!on && old) {
            dock->setTitleBarWidget(nullptr);
            old->deleteLater();
        }
    }
    for (QAction* key : presentationKeys_) key->setEnabled(on);
    if (on) {
        if (presentationSize_.isValid()) {
            showNormal();
            resize(presentationSize_);
        } else {
            showFullScreen();
        }
        layOutForPresenting();
        // Again once the window has its full size (full screen comes through the event loop).
        QTimer::singleShot(0, this, [this] { layOutForPresenting(); });
    } else {  // every dock, toolbar and the window itself where they were
        showNormal();
        view_->setFramePose(false);
        // After the event loop has applied the normal state, the smaller fonts and the
        // removed dock titles: restored now, the window would keep the presenting layout's
        // minimum width and the docks would be laid out again for the old sizes.
        // Twice: the first pass lets the widgets take their smaller minimum sizes, which
        // some (the toolbars) only do after a layout pass at the new size.
        const auto restore = [this] {
            if (presenting_) return;
            for (QWidget* w : findChildren<QWidget*>())
                if (w->layout()) w->layout()->activate();
            setGeometry(geometryBeforePresenting_);
            restoreState(layoutBeforePresenting_);
        };
        QTimer::singleShot(0, this, [this, restore] {
            restore();
            QTimer::singleShot(0, this, restore);
        });
    }
}

void MainWindow::layOutForPresenting() {
    if (!presenting_) return;
    auto* derivationDock = findChild<QDockWidget*>("derivation");
    auto* plots = findChild<QDockWidget*>("plots");
    if (!derivationDock || !plots) return;
    // The plots under the derivation, both beside the 3D view: on a projector's 16:9 the
    // robot gets the left 58 % at full height instead of a strip above a plot.
    if (dockWidgetArea(plots) != Qt::RightDockWidgetArea || dockWidgetArea(derivationDock) != Qt::RightDockWidgetArea) {
        derivationDock->show();
        splitDockWidget(derivationDock, plots, Qt::Vertical);
    }
    const QSize area = size();
    resizeDocks({derivationDock}, {area.width() * 42 / 100}, Qt::Horizontal);
    resizeDocks({derivationDock, plots}, {area.height() * 56 / 100, area.height() * 44 / 100}, Qt::Vertical);
    showPlotTab("energy");
    derivationTabs_->setCurrentWidget(typeset_);
    // The camera on the robot as it stands, fitted to the view's new shape.
    QTimer::singleShot(0, view_, [this] {
        if (presenting_) view_->setFramePose(true);
    });
}

void MainWindow::keyPressEvent(QKeyEvent* e) {
    switch (e->key()) {
        case Qt::Key_Space: playback_->togglePlay(); return;
        case Qt::Key_Right: derivation_->nextStep(); return;
        case Qt::Key_Left: derivation_->previousStep(); return;
        case Qt::Key_F: view_->fit(); return;
        case Qt::Key_Plus: playback_->faster(); return;
        case Qt::Key_Minus: playback_->slower(); return;
        case Qt::Key_Escape:
            if (presenting_) setPresentationMode(false);
            return;
        default: QMainWindow::keyPressEvent(e);
    }
}

// ---------------------------------------------------------------- files

bool MainWindow::openFile(const QString& path, QStringList* errors, bool quiet) {
    if (opening_) {
        if (errors) *errors = QStringList{tr("%1: another file is being opened").arg(path)};
        return false;
    }
    derive_.cancel();  // loading checks the scene under the GiNaC lock
    // The check runs on the document's worker; the window keeps drawing meanwhile.
    opening_ = true;
    statusBar()->showMessage(tr("Opening %1…").arg(QFileInfo(path).fileName()));
    QEventLoop loop;
    bool done = false, loaded = false;
    QStringList found;
    doc_.loadFileInBackground(path, [&](bool ok, const QStringList& lines) {
        done = true;
        loaded = ok;
        found = lines;
        loop.quit();
    });
    if (!done) loop.exec(QEventLoop::ExcludeUserInputEvents);
    opening_ = false;
    statusBar()->clearMessage();
    if (!loaded) {
        derive_.resume();
        if (errors) *errors = found;
        if (!quiet) {
            QMessageBox box(QMessageBox::Warning, tr("Cannot open %1").arg(QFileInfo(path).fileName()),
                            tr("The scene has errors; the open scene is kept."), QMessageBox::Ok, this);
            box.setDetailedText(found.join('\n'));
            box.setInformativeText(found.mid(0, 6).join('\n'));
            box.exec();
        }
        statusBar()->showMessage(tr("%1: %n error(s), nothing changed", "", found.size()).arg(path), 8000);
        return false;
    }
    if (!path.startsWith(":/")) addRecent(QFileInfo(path).absoluteFilePath());
    discardRecovery();  // the copy of the scene open before, if it was not saved: asked in maybeSave
    originalHash_ = CrashRecovery::hashOfFile(path);
    // The editor opens on the tab that describes the scene: a typed Lagrangian's, or the DH table.
    editorTabs_->setCurrentWidget(doc_.json().contains("lagrangian") ? lagrangianPage_ : editorTabs_->widget(0));
    playback_->setTime(0);
    updateTitle();
    return true;
}

bool MainWindow::saveTo(const QString& path, QString* error) {
    try {
        doc_.saveFile(path);
    } catch (const std::exception& e) {
        if (error) *error = QString::fromUtf8(e.what());
        return false;
    }
    addRecent(QFileInfo(path).absoluteFilePath());
    discardRecovery();
    originalHash_ = CrashRecovery::hashOfFile(path);
    updateTitle();
    return true;
}

void MainWindow::open() {
    if (!maybeSave()) return;
    const QString path = QFileDialog::getOpenFileName(this, tr("Open scene"), QFileInfo(doc_.path()).absolutePath(), sceneFilter());
    if (!path.isEmpty()) openFile(path);
}

bool MainWindow::save() {
    if (doc_.path().isEmpty()) return saveAs();
    QString error;
    if (!saveTo(doc_.path(), &error)) {
        QMessageBox::critical(this, tr("Save"), error);
        return false;
    }
    return true;
}

bool MainWindow::saveAs() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Save scene as"), doc_.path(), sceneFilter());
    if (path.isEmpty()) return false;
    QString error;
    if (!saveTo(path, &error)) {
        QMessageBox::critical(this, tr("Save"), error);
        return false;
    }
    return true;
}

bool MainWindow::maybeSave() {
    if (!doc_.isModified() || !askBeforeClosing_) return true;
    const auto answer = QMessageBox::warning(this, tr("Unsaved changes"), tr("The scene has unsaved changes. Save them?"),
                                             QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save) return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::rememberLayout() {
    remembersLayout_ = true;
    QSettings settings("LagrangeLab", "LagrangeLab");
    if (const QByteArray g = settings.value("window/geometry").toByteArray(); !g.isEmpty()) restoreGeometry(g);
    if (const QByteArray s = settings.value("window/state").toByteArray(); !s.isEmpty()) restoreState(s);
}

void MainWindow::closeEvent(QCloseEvent* e) {
    if (!maybeSave()) {
        e->ignore();
        return;
    }
    if (remembersLayout_) {  // closed while presenting: the layout from before
        QSettings settings("LagrangeLab", "LagrangeLab");
        if (!presenting_) settings.setValue("window/geometry", saveGeometry());
        settings.setValue("window/state", presenting_ ? layoutBeforePresenting_ : saveState());
    }
    discardRecovery();
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
        if (maybeSave()) openFile(path);
    });
}

void MainWindow::updateTitle() {
    const QString name = doc_.path().isEmpty() ? QString::fromStdString(doc_.validScene().name) : QFileInfo(doc_.path()).fileName();
    setWindowTitle(tr("%1%2 — LagrangeLab").arg(name, doc_.isModified() ? "*" : ""));
}

void MainWindow::addRecent(const QString& path) {
    QSettings settings("LagrangeLab", "LagrangeLab");
    QStringList recent = settings.value("recent").toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    settings.setValue("recent", recent.mid(0, kMaxRecent));
    rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu() {
    recentMenu_->clear();
    QSettings settings("LagrangeLab", "LagrangeLab");
    for (const QString& path : settings.value("recent").toStringList())
        recentMenu_->addAction(path, this, [this, path] {
            if (maybeSave()) openFile(path);
        });
    recentMenu_->setEnabled(!recentMenu_->isEmpty());
}

// ---------------------------------------------------------------- recovery

QString MainWindow::editorTab() const { return editorTabs_->tabText(editorTabs_->currentIndex()); }

void MainWindow::writeRecovery() {
    const QString original = doc_.path().startsWith(":/") ? QString() : doc_.path();
    try {
        recovery_.write(original, originalHash_, doc_.json());
    } catch (const std::exception& e) {
        statusBar()->showMessage(tr("Autosave failed: %1").arg(QString::fromUtf8(e.what())), 8000);
    }
}

void MainWindow::discardRecovery() { recovery_.discard(); }

std::vector<RecoveryCopy> MainWindow::recoveriesLeft(QStringList* damaged) const { return recovery_.leftBehind(damaged); }

bool MainWindow::isOwnScene(const RecoveryCopy& copy) const {
    return !copy.original.isEmpty() && !doc_.path().isEmpty() && QFileInfo(copy.original) == QFileInfo(doc_.path());
}

QString MainWindow::recoveryQuestion(const RecoveryCopy& copy) const {
    const QString name = copy.original.isEmpty() ? tr("a new scene that was never saved")
                                                 : tr("%1 (in %2)").arg(QFileInfo(copy.original).fileName(),
                                                                        QFileInfo(copy.original).absolutePath());
    QString text = tr("LagrangeLab did not close normally while %1 had unsaved edits (autosaved %2).")
                       .arg(name, QLocale().toString(copy.written.toLocalTime(), QLocale::ShortFormat));
    SceneJson before = SceneJson::object();
    if (!copy.original.isEmpty()) {
        if (!QFileInfo::exists(copy.original)) {
            text += "\n\n" + tr("%1 no longer exists: the recovered scene is all that is left of it.").arg(copy.original);
        } else {
            if (CrashRecovery::originalChanged(copy))
                text += "\n\n" + tr("Warning: %1 has changed on disk since these edits were made. Restoring puts the "
                                     "recovered scene on top of the file as it is now; undo returns to it.")
                                      .arg(copy.original);
            QFile f(copy.original);
            if (f.open(QIODevice::ReadOnly)) try {
                    before = SceneJson::parse(f.readAll().toStdString());
                } catch (const std::exception&) {
                }
        }
    }
    const QStringList changes = CrashRecovery::changes(before, copy.scene);
    if (!changes.isEmpty()) text += "\n\n" + tr("What the edits change:") + "\n  " + changes.join("\n  ");
    return text;
}

bool MainWindow::restoreRecovery(const RecoveryCopy& copy) {
    if (!isOwnScene(copy)) return false;
    // The file as it is, then the recovered JSON as an unsaved, undoable edit on top:
    // saving writes it back to the file.
    doc_.replace(copy.scene, tr("Restore unsaved edits"));
    updateTitle();
    writeRecovery();  // this window's own copy first, then the crashed one goes
    CrashRecovery::remove(copy);
    return true;
}

void MainWindow::offerRecovery() {
    QStringList damaged;
    const std::vector<RecoveryCopy> copies = recoveriesLeft(&damaged);
    for (const QString& line : damaged) statusBar()->showMessage(line, 15000);
    for (const RecoveryCopy& copy : copies) {
        QMessageBox box(QMessageBox::Question, tr("Restore unsaved work?"), recoveryQuestion(copy), QMessageBox::NoButton, this);
        if (isOwnScene(copy)) {
            QPushButton* restore = box.addButton(tr("Restore the edits"), QMessageBox::AcceptRole);
            QPushButton* discard = box.addButton(tr("Discard them"), QMessageBox::DestructiveRole);
            box.addButton(tr("Keep for later"), QMessageBox::RejectRole);
            box.exec();
            if (box.clickedButton() == restore) restoreRecovery(copy);
            else if (box.clickedButton() == discard) CrashRecovery::remove(copy);
            continue;
        }
        // Another scene's edits: never in place of the scene asked for.
        QPushButton* open = box.addButton(tr("Open them in a new window"), QMessageBox::AcceptRole);
        QPushButton* discard = box.addButton(tr("Discard them"), QMessageBox::DestructiveRole);
        box.addButton(tr("Keep for later"), QMessageBox::RejectRole);
        box.exec();
        if (box.clickedButton() == discard) {
            CrashRecovery::remove(copy);
        } else if (box.clickedButton() == open) {
            QString scene = copy.original;
            if (scene.isEmpty() || !QFileInfo::exists(scene)) {  // written out first, so nothing is lost
                scene = QFileInfo(copy.file).absolutePath() + "/recovered-" +
                        copy.written.toString("yyyyMMdd-HHmmss") + ".json";
                try {
                    saveFileAtomically(scene.toStdString(), copy.scene.dump(2), Backup::None);
                } catch (const std::exception& e) {
                    QMessageBox::critical(this, tr("Restore unsaved work"), QString::fromUtf8(e.what()));
                    continue;
                }
                CrashRecovery::remove(copy);
            }
            QProcess::startDetached(QCoreApplication::applicationFilePath(), {scene});
        }
    }
}

// ---------------------------------------------------------------- exports

QImage MainWindow::screenshot() {
    // The window as the screen shows it: QWidget::grab() would miss the GL view's overlay.
    if (QScreen* screen = windowHandle() ? windowHandle()->screen() : QGuiApplication::primaryScreen()) {
        const QPixmap pixmap = screen->grabWindow(winId());
        if (!pixmap.isNull()) return pixmap.toImage();
    }
    return grab().toImage();
}

void MainWindow::exportScreenshot() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Save screenshot"), "screenshot.png", tr("PNG images (*.png)"));
    if (path.isEmpty()) return;
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    screenshot().save(&buffer, "PNG");
    try {
        saveFileAtomically(path.toStdString(), bytes.toStdString(), Backup::None);
    } catch (const std::exception& e) {
        QMessageBox::critical(this, tr("Screenshot"), QString::fromUtf8(e.what()));
    }
}

void MainWindow::exportPlot() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export plot"), "energy.png", tr("PNG (*.png);;SVG (*.svg);;CSV (*.csv)"));
    QString error;
    if (!path.isEmpty() && !exportPlotTo(path, &error)) QMessageBox::critical(this, tr("Export plot"), error);
}

bool MainWindow::exportPlotTo(const QString& path, QString* error) {
    TrajectoryChart* chart = bottomTabs_->currentWidget() == jointsChart_ ? jointsChart_ : energy_;
    try {
        if (!result_) throw std::runtime_error(tr("nothing to export: the simulation has not finished").toStdString());
        if (path.endsWith(".csv", Qt::CaseInsensitive))
            chart->exportCsv(path);
        else
            chart->exportImage(path);
    } catch (const std::exception& e) {
        if (error) *error = QString::fromUtf8(e.what());
        return false;
    }
    statusBar()->showMessage(tr("Plot written to %1").arg(path), 8000);
    return true;
}

// An export finished on a worker: said in the status bar, an error in a dialog unless the
// caller is a test or script (no dialog asked).
static void reportExport(MainWindow* window, QStatusBar* bar, const QString& path, const QString& error, bool dialog) {
    if (error.isEmpty())
        bar->showMessage(MainWindow::tr("Written: %1").arg(path), 10000);
    else if (error != "cancelled" && dialog)
        QMessageBox::critical(window, MainWindow::tr("Export"), error);
    else
        bar->showMessage(MainWindow::tr("Export of %1 stopped: %2").arg(path, error), 10000);
}

void MainWindow::exportDerivation() {
    QString filter;
    QString path = QFileDialog::getSaveFileName(
        this, tr("Export derivation"), "derivation.pdf",
        tr("PDF, typeset (*.pdf);;SVG, typeset, a file per page (*.svg);;PNG, typeset, a file per page (*.png);;LaTeX (*.tex);;Text (*.txt)"),
        &filter);
    // A name typed without an extension takes the chosen filter's (*.svg → .svg).
    if (const qsizetype star = filter.indexOf("(*."); !path.isEmpty() && QFileInfo(path).suffix().isEmpty() && star >= 0)
        path += filter.mid(star + 2, filter.indexOf(')', star) - star - 2);
    QString error;
    if (!path.isEmpty() && !exportDerivationTo(path, &error)) QMessageBox::critical(this, tr("Export derivation"), error);
}

bool MainWindow::exportDerivationTo(const QString& path, QString* error) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix != "pdf" && suffix != "svg" && suffix != "png" && suffix != "tex" && suffix != "txt") {
        if (error) *error = tr("%1: expected a .pdf, .svg, .png, .tex or .txt file").arg(path);
        return false;
    }
    if (!derived_ || !derived_->display) {
        if (error) *error = tr("nothing to export: the derivation has not finished");
        return false;
    }
    // The document on screen: no new derivation. Typeset pages as `derive --format
    // pdf|svg|png` (ui/derivation_pages: SVG and PNG write page k beside FILE as
    // STEM-k.EXT), LaTeX and text rendered from the same display trees.
    auto display = derived_->display;
    QThreadPool::globalInstance()->start([this, display, path, suffix, self = QPointer<MainWindow>(this)] {
        QString failure, shown = path;  // shown: what the status bar names
        try {
            if (suffix == "pdf") {
                std::string reason;
                if (!writePdf(*display, path, reason)) failure = QString::fromStdString(reason);
            } else if (suffix == "svg" || suffix == "png") {
                std::string reason;
                const DerivationPages pages = paginate(*display);
                std::vector<QString> written;
                if (!(suffix == "svg" ? writeSvg(pages, path, reason, &written) : writePng(pages, path, reason, &written)))
                    failure = QString::fromStdString(reason);
                else if (written.size() > 1)
                    shown = tr("%1 … %2 (%n pages)", nullptr, static_cast<int>(written.size())).arg(path, QFileInfo(written.back()).fileName());
                if (failure.isEmpty())
                    if (const auto older = pagesBeyond(path, static_cast<int>(written.size())); !older.empty())
                        shown += (older.size() == 1
                                      ? tr("; 1 page file of an earlier, longer export remains beside it, not deleted: %1")
                                      : tr("; %n page files of an earlier, longer export remain beside it, not deleted: %1",
                                           nullptr, static_cast<int>(older.size())))
                                     .arg(fileNameRange(older));
            } else {
                const auto format = suffix == "tex" ? present::DocumentFormat::Latex : present::DocumentFormat::Text;
                saveFileAtomically(path.toStdString(), present::renderDocument(*display, format), Backup::None);
            }
        } catch (const std::exception& e) {
            failure = QString::fromUtf8(e.what());
        }
        QMetaObject::invokeMethod(qApp, [self, path, shown, failure] {
            if (!self) return;
            reportExport(self, self->statusBar(), shown, failure, self->isVisible());
            emit self->exportFinished(path, failure);
        }, Qt::QueuedConnection);
    });
    statusBar()->showMessage(tr("Writing %1…").arg(path));
    return true;
}

void MainWindow::exportAnimation() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export animation"), "animation.mp4", tr("MP4 (*.mp4);;WebM (*.webm);;GIF (*.gif);;PNG still (*.png)"));
    QString error;
    if (!path.isEmpty() && !exportAnimationTo(path, &error)) QMessageBox::critical(this, tr("Export animation"), error);
}

bool MainWindow::exportAnimationTo(const QString& path, QString* error, double duration, bool withDialog, QSize slide) {
    if (!result_ || !sampler_) {
        if (error) *error = tr("nothing to export: the simulation has not finished");
        return false;
    }
    ExportSettings settings;
    try {
        settings.out = path.toStdString();
        settings.kind = outputKindFor(settings.out);
        const std::string problem = outputProblem(settings.out, settings.kind);
        if (!problem.empty()) throw std::runtime_error(problem);
    } catch (const std::exception& e) {
        if (error) *error = QString::fromUtf8(e.what());
        return false;
    }
    settings.duration = duration > 0 ? std::min(duration, sampler_->endTime() - sampler_->startTime()) : sampler_->endTime() - sampler_->startTime();
    settings.speed = playback_->speed();
    settings.at = playback_->time();
    settings.trail = view_->showTrail();
    settings.frames = view_->showFrames();
    settings.frameLabels = view_->showLabels();
    if (slide.isValid()) {
        settings.composite = true;
        settings.width = slide.width(), settings.height = slide.height();
        if (derived_ && derived_->display) {
            const present::DisplayDocument& document = *derived_->display;
            const present::DisplayStep* shown = document.step(typeset_->step() <= 8 ? typeset_->step() : 8);
            if (!shown && !document.steps.empty()) shown = &document.steps.back();
            if (shown) settings.step = std::make_shared<const present::DisplayStep>(*shown);
            settings.language = derived_->display->language;
        }
    }
    auto result = result_;
    exportOnWorker(path, tr("Rendering %1…").arg(QFileInfo(path).fileName()), withDialog,
                   [result, settings](const std::function<void(double)>& progress, const std::atomic<bool>* cancel) {
                       ll::ui::exportAnimation(*result->scene, result->simulation.trajectory, settings, progress, cancel);
                   });
    return true;
}

// `work` on a worker, with a progress dialog and Cancel when `withDialog`; then the status
// bar (or a message box) says how it went and exportFinished(target, error) is emitted.
void MainWindow::exportOnWorker(const QString& target, const QString& label, bool withDialog, ExportWork work) {
    QPointer<QProgressDialog> dialog;
    auto cancel = std::make_shared<std::atomic<bool>>(false);
    if (withDialog) {
        dialog = new QProgressDialog(label, tr("Cancel"), 0, 1000, this);
        dialog->setWindowModality(Qt::WindowModal);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->setMinimumDuration(0);
        connect(dialog, &QProgressDialog::canceled, this, [cancel] { cancel->store(true); });
        dialog->show();
    }
    QThreadPool::globalInstance()->start([self = QPointer<MainWindow>(this), dialog, cancel, work = std::move(work), target, withDialog] {
        QString failure;
        try {
            work([dialog](double f) {
                QMetaObject::invokeMethod(qApp, [dialog, f] {
                    if (dialog) dialog->setValue(static_cast<int>(f * 1000));
                }, Qt::QueuedConnection);
            }, cancel.get());
        } catch (const std::exception& e) {
            failure = QString::fromUtf8(e.what());
        }
        QMetaObject::invokeMethod(qApp, [self, dialog, target, failure, withDialog] {
            if (dialog) dialog->close();
            if (!self) return;
            reportExport(self, self->statusBar(), target, failure, withDialog);
            emit self->exportFinished(target, failure);
        }, Qt::QueuedConnection);
    });
}

bool MainWindow::exportLabReportTo(const QString& dir, QString* error, bool withDialog) {
    if (!result_ || !derived_ || !derived_->display) {
        if (error) *error = tr("nothing to report yet: the simulation or the derivation has not finished");
        return false;
    }
    LabReportInput input;  // copies: the worker shares nothing with the window
    input.scene = *result_->scene;
    input.simulation = result_->simulation;
    input.display = derived_->display;
    input.sceneText = doc_.text();
    input.sceneFileName = doc_.path().isEmpty() ? "scene.json" : QFileInfo(doc_.path()).fileName().toStdString();
    exportOnWorker(dir, tr("Writing the lab report into %1…").arg(dir), withDialog,
                   [input = std::move(input), dir](const std::function<void(double)>& progress, const std::atomic<bool>* cancel) {
                       writeLabReport(input, dir.toStdString(), progress, cancel);
                   });
    return true;
}

// ---------------------------------------------------------------- parameters

// Whether `typed` (trimmed) can name a new parameter: an identifier no parameter has.
bool MainWindow::freeParameterName(const QString& typed, QString* error) const {
    static const QRegularExpression identifier("^[A-Za-z_][A-Za-z0-9_]*$");
    const QString trimmed = typed.trimmed();
    if (!identifier.match(trimmed).hasMatch()) {
        if (error) *error = tr("parameter name '%1': letters, digits and _ only, starting with a letter").arg(typed);
        return false;
    }
    if (!doc_.value("/parameters/" + trimmed.toStdString()).is_null()) {
        if (error) *error = tr("parameter name '%1': there is a parameter of that name").arg(trimmed);
        return false;
    }
    return true;
}

bool MainWindow::addParameter(const QString& name, const QString& value, QString* error) {
    const QString trimmed = name.trimmed();
    if (!freeParameterName(name, error)) return false;
    // The loader checks the rest (reserved names such as c1 or s12, the value) and marks it.
    doc_.setValue("/parameters/" + trimmed.toStdString(), SceneDocument::parseCell(value), tr("Add parameter %1").arg(trimmed));
    return true;
}

bool MainWindow::renameParameter(const QString& from, const QString& to, QString* error) {
    const QString trimmed = to.trimmed();
    if (doc_.value("/parameters/" + from.toStdString()).is_null()) {
        if (error) *error = tr("no parameter '%1'").arg(from);
        return false;
    }
    if (trimmed == from) return true;
    if (!freeParameterName(to, error)) return false;
    // The loader checks the rest (a reserved name such as c1, a clash with a coordinate).
    doc_.replace(renamedParameter(doc_.json(), from.toStdString(), trimmed.toStdString()),
                 tr("Rename parameter %1 to %2").arg(from, trimmed));
    return true;
}

void MainWindow::removeParameter(const QString& name) {
    doc_.setValue("/parameters/" + name.toStdString(), SceneJson(), tr("Remove parameter %1").arg(name));
}

}  // namespace ll::ui
