#pragma once
// The LagrangeLab window: the model editor (left), the 3D view with playback (centre),
// the derivation (right), the plots, teach mode and work–precision (bottom) and a status
// line. Every edit goes through the SceneDocument's undo stack; each valid edit is
// re-simulated (LiveSimulation) and re-derived once (LiveDerivation: one worker whose
// result both derivation tabs show) in worker threads, and the newest result replaces
// the views. Files: open, save, save as (atomic, PATH.bak),
// recent files, the example gallery, drag and drop, an autosaved recovery copy offered
// back after a crash, a question before unsaved work is closed.
#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <QMainWindow>
#include <QStringList>
#include <QTimer>

#include "core/visual/trajectory_sampler.hpp"
#include "ui/entry_selection.hpp"
#include "ui/live_derivation.hpp"
#include "ui/edit_frame.hpp"
#include "ui/live_simulation.hpp"
#include "ui/crash_recovery.hpp"
#include "ui/scene_document.hpp"

class QAction;
class QLabel;
class QListWidget;
class QMenu;
class QPlainTextEdit;
class QProgressBar;
class QTabWidget;
class QTableView;
class QComboBox;

namespace ll::ui {

class DerivationPanel;
class DerivationView;
class EntryList;
class PropertiesPanel;
class TorquePane;
class FieldListModel;
class JointTableModel;
class PlaybackBar;
class SceneView;
class TeachPanel;
class TrajectoryChart;
class WorkPrecisionPane;
class DhStepPanel;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Opens `path` (a file or a ":/examples/…" resource). The scene is checked on a worker
    // thread while the window keeps drawing (this call waits in a local event loop). On
    // failure the errors are shown (a dialog unless `quiet`), returned in *errors, and the
    // open document is kept.
    bool openFile(const QString& path, QStringList* errors = nullptr, bool quiet = false);
    bool saveTo(const QString& path, QString* error = nullptr);

    // Autosave (ui/crash_recovery.hpp): this window's recovery copy, written every 5 s
    // while there are unsaved edits and removed on save or discard.
    void writeRecovery();
    void discardRecovery();
    QString recoveryCopyFile() const { return recovery_.ownFile(); }
    // Copies left by windows that crashed (named in *damaged: those set aside as cut short).
    std::vector<RecoveryCopy> recoveriesLeft(QStringList* damaged = nullptr) const;
    // Whether `copy` holds edits of the scene this window has open.
    bool isOwnScene(const RecoveryCopy& copy) const;
    // The question asked about a copy: the file named, when it was saved, a warning first
    // when the file changed on disk since, and what the edits change.
    QString recoveryQuestion(const RecoveryCopy& copy) const;
    // Restores a copy of this window's scene as an undoable, unsaved edit on top of the
    // file as it is; the copy is replaced by this window's own.
    bool restoreRecovery(const RecoveryCopy& copy);
    // Asks about every copy left by a crash: this scene's as a restore, others' apart
    // (open in a new window, discard, or keep for later): never in place of this scene.
    void offerRecovery();

    // Screenshot of the whole window, GL view included.
    QImage screenshot();
    void setAskBeforeClosing(bool on) { askBeforeClosing_ = on; }
    // The window's size and its docks' layout as the user left them last time: restored
    // now, and saved when it closes (a user's window; screenshots and tests keep theirs).
    void rememberLayout();

    // For tests and benchmarks.
    SceneDocument& document() { return doc_; }
    JointTableModel& jointModel() { return *joints_; }
    // The editor's smaller tabs: parameters, initial state and gravity, a Lagrangian's fields.
    FieldListModel& parameterModel() { return *parameters_; }
    FieldListModel& initialStateModel() { return *initial_; }
    FieldListModel& lagrangianModel() { return *lagrangian_; }
    SceneView& sceneView() { return *view_; }
    DerivationPanel& derivationPanel() { return *derivation_; }
    DerivationView& derivationView() { return *typeset_; }
    // The longest an edit's repaint waits for its result (100 ms; tests lengthen it so a
    // loaded machine does not decide what they see).
    void setEditHoldLimit(int milliseconds) { editFrame_->setLimit(milliseconds); }
    TrajectoryChart& energyChart() { return *energy_; }
    TrajectoryChart& jointsChart() { return *jointsChart_; }
    PlaybackBar& playback() { return *playback_; }
    TeachPanel& teachPanel() { return *teach_; }
    LiveSimulation& liveSimulation() { return live_; }
    LiveDerivation& liveDerivation() { return derive_; }
    WorkPrecisionPane& workPrecisionPane() { return *workPrecision_; }
    DhStepPanel& dhStepPanel() { return *dhSteps_; }
    const LiveResult* result() const { return result_.get(); }
    const LiveResult* ghostResult() const { return ghost_.get(); }
    // The newest derivation shown (null before the first one).
    const DerivationResult* derivation() const { return derived_.get(); }
    bool presenting() const { return presenting_; }
    QString statusText() const;
    QStringList diagnosticLines() const;
    // Shows `n` 0..8 of the derivation; poses the robot (teach mode).
    void showDerivationStep(int n);
    void teach(const Eigen::VectorXd& q);
    // The derivation linked to the motion (ui/entry_selection): pick an entry by id as
    // typed (b12, g2, beta23_4; false when the derivation shown has none), pick link
    // `link` (0-based; −1 clears); the pick shows in every view.
    bool selectEntry(const QString& id);
    void pickLink(int link);
    EntrySelection& selection() { return selection_; }
    EntryList& entryList() { return *entryList_; }
    TrajectoryChart& entryChart() { return *entryChart_; }
    TorquePane& torquePane() { return *torques_; }
    PropertiesPanel& propertiesPanel() { return *properties_; }
    QString readoutText() const;
    QString readoutHint() const;
    // Shows a tab of the plots dock by name: energy, joints, teach, torques, properties,
    // work-precision, dh-steps (false: no such tab).
    bool showPlotTab(const QString& name);
    // Shows the derivation dock's tab: typeset, text or entries.
    void showDerivationView(const QString& name);
    // The run's analysis shown (torques and properties; null until it arrives).
    const RunAnalysis* analysis() const { return analysis_.get(); }
    // Runs a ghost with `integrator` ("" removes it).
    void setGhostIntegrator(const QString& integrator);
    // Presentation mode: the 3D view on the left (at least half the screen), the current
    // derivation step above the energy plot on the right, every text large; keys only.
    void setPresentationMode(bool on);
    // What presentation mode fills: the screen (an invalid size, the default) or, for a
    // scripted picture (--present --size), a window of `size`.
    void setPresentationSize(QSize size) { presentationSize_ = size; }
    // The language and notation the derivation is shown in (View → Language, Notation):
    // the derivation on screen is relabelled at once, not derived again.
    void setPresentation(const present::Presentation& presentation);
    const present::Presentation& presentation() const { return presentation_; }
    // Parameters: one undoable edit each. addParameter refuses a name that is not an
    // identifier or is taken (false, the reason in *error).
    bool addParameter(const QString& name, const QString& value, QString* error = nullptr);
    void removeParameter(const QString& name);
    // Renames a parameter and every expression that uses it (ui/parameter_rename): one
    // undoable edit. Refuses an invalid or taken name with the reason in `error`.
    bool renameParameter(const QString& from, const QString& to, QString* error = nullptr);

    // Exports without a file dialog (the menu's entries ask for the path, then call
    // these). Plot: the tab shown (energy or joints) as .png, .svg or .csv, at once.
    // Derivation: .pdf (typeset, as `derive --format pdf`), .tex or .txt, from the
    // derivation on screen, written on a worker. Animation: .mp4, .webm, .gif, a .png
    // still or a folder of frames by the offscreen renderer (`render`), on a worker with
    // `progress` (optional) and a cancel button when `withDialog`. The two on workers
    // emit exportFinished when done; all return false with the reason when they cannot
    // start.
    bool exportPlotTo(const QString& path, QString* error = nullptr);
    bool exportDerivationTo(const QString& path, QString* error = nullptr);
    // `slide`: a valid size renders the composite slide (ui/composite_frame.hpp) of that size
    // with the derivation step shown (8 when the window shows the pose results).
    bool exportAnimationTo(const QString& path, QString* error = nullptr, double duration = -1, bool withDialog = true,
                           QSize slide = {});
    // Lab report (ui/lab_report.hpp): the bundle into folder `dir`, from the run and the
    // derivation on screen and the scene as edited, on a worker; exportFinished(dir, …).
    bool exportLabReportTo(const QString& dir, QString* error = nullptr, bool withDialog = true);

signals:
    // A simulation result is on screen (the 3D view, plots and playback updated).
    void resultShown(int request);
    // An export on a worker is done: `error` empty when `path` was written.
    void exportFinished(const QString& path, const QString& error);

protected:
    void closeEvent(QCloseEvent* e) override;
    void dragEnterEvent(QDragEnterEvent* e) override;
    void dropEvent(QDropEvent* e) override;
    void keyPressEvent(QKeyEvent* e) override;

private:
    void buildEditor();
    void buildCentre();
    void buildDocks();
    void buildMenus();
    void documentChanged();
    void validSceneChanged();
    void showResult(std::shared_ptr<const LiveResult> result);
    void showGhost(std::shared_ptr<const LiveResult> result);
    void showDerivation(std::shared_ptr<const DerivationResult> result);
    void showAnalysis(std::shared_ptr<const RunAnalysis> analysis);
    void pickedInDerivation(int step, int item, int row, int col);
    void selectionChanged();
    void selectionValueChanged();
    void showTime(double t);
    void updatePoseResults();
    bool freeParameterName(const QString& typed, QString* error) const;
    void refreshJson();
    void showTeachPose(const Eigen::VectorXd& q);
    void updateTitle();
    void addRecent(const QString& path);
    void rebuildRecentMenu();
    bool maybeSave();
    void open();
    bool save();
    bool saveAs();
    void exportScreenshot();
    void exportPlot();
    void exportDerivation();
    void exportAnimation();

    SceneDocument doc_;
    LiveSimulation live_, ghostLive_;
    LiveDerivation derive_;
    EntrySelection selection_;
    std::shared_ptr<const RunAnalysis> analysis_;
    std::shared_ptr<const DerivationResult> derived_;   // as shown: in presentation_
    std::shared_ptr<const DerivationResult> derivedAsDerived_;  // as the worker made it (English, the notes' notation)
    present::Presentation presentation_;
    QMenu* languageMenu_ = nullptr;
    QMenu* notationMenu_ = nullptr;
    std::shared_ptr<const LiveResult> result_, ghost_;
    std::unique_ptr<TrajectorySampler> sampler_, ghostSampler_;
    std::vector<Eigen::Vector3d> effectorPath_;  // end effector at every sample
    Eigen::VectorXd q_, qd_;
    QString ghostIntegrator_;

    JointTableModel* joints_ = nullptr;
    FieldListModel *parameters_ = nullptr, *initial_ = nullptr, *solver_ = nullptr, *lagrangian_ = nullptr;
    QTableView *dhView_ = nullptr, *inertialView_ = nullptr;
    QComboBox* convention_ = nullptr;
    QPlainTextEdit* jsonEdit_ = nullptr;
    QListWidget* diagnostics_ = nullptr;
    SceneView* view_ = nullptr;
    PlaybackBar* playback_ = nullptr;
    DerivationPanel* derivation_ = nullptr;
    DerivationView* typeset_ = nullptr;
    TrajectoryChart *energy_ = nullptr, *jointsChart_ = nullptr, *entryChart_ = nullptr;
    EntryList* entryList_ = nullptr;
    TorquePane* torques_ = nullptr;
    PropertiesPanel* properties_ = nullptr;
    QLabel* readout_ = nullptr;
    QTabWidget* derivationTabs_ = nullptr;
    TeachPanel* teach_ = nullptr;
    WorkPrecisionPane* workPrecision_ = nullptr;
    DhStepPanel* dhSteps_ = nullptr;
    QTabWidget *editorTabs_ = nullptr, *bottomTabs_ = nullptr;
    QWidget* lagrangianPage_ = nullptr;

public:
    // The editor's tab shown (tests): "DH", "Lagrangian", ...
    QString editorTab() const;
    QLabel* status_ = nullptr;
    QMenu* recentMenu_ = nullptr;
    QDockWidget *modelDock_ = nullptr;
    QTableView* parameterView_ = nullptr;
    QList<QAction*> presentationKeys_;  // space, arrows, F, +, −: live only when presenting
    QTimer autosave_;
    CrashRecovery recovery_{CrashRecovery::defaultDirectory()};
    QString originalHash_;  // of the scene file's bytes as opened or last saved
    EditFrame* editFrame_ = nullptr;  // one repaint per edit: the cell and its result together
    bool askBeforeClosing_ = true;
    bool presenting_ = false;
    bool remembersLayout_ = false;
    QByteArray layoutBeforePresenting_;  // restored when leaving presentation mode, with …
    QRect geometryBeforePresenting_;     // … the window's place and size
    QSize presentationSize_;             // invalid: presenting fills the screen
    using ExportWork = std::function<void(const std::function<void(double)>& progress, const std::atomic<bool>* cancel)>;
    void exportOnWorker(const QString& target, const QString& label, bool withDialog, ExportWork work);
    void layOutForPresenting();
    bool jsonStale_ = true;  // the JSON tab's text is older than the document
    bool teaching_ = false;
    bool opening_ = false;  // a file is being checked (openFile waits for its worker)
    int shownStructure_ = -1;  // joints/coordinates of the scene on screen (a change refits the camera)
    QString shownName_;
};

}  // namespace ll::ui
