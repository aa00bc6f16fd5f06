#pragma once
// The LagrangeLab window. MainWindow composes; it implements no feature itself. It owns
// the edited document (ui/document/scene_document) and the workers that re-simulate and
// re-derive each valid edit (LiveSimulation, LiveDerivation: the newest edit wins), builds
// the widgets (the model editor on the left, the 3D view with playback in the centre, the
// derivation on the right, the plots below, a status line), shows each result when it
// arrives, and hands the widgets to one class per feature:
//
//   SceneFiles        open, save, recent files, examples       ui/window/scene_files.hpp
//   Autosave          the recovery copy and the offer after a crash  ui/window/autosave.hpp
//   ExportActions     screenshot, plot, derivation, animation, slides, lab report
//   EntryLinking      an entry or link picked shows in every view    ui/window/entry_linking.hpp
//   DhStepLink        the DH step-through in the 3D view and the table
//   PresentationMode  the projector layout and its keys
//   LanguageMenu      the derivation's language and notation
//   GhostRun          the same scene with a cheaper integrator beside it (or a controller's reference)
//   ControlTuning     the Tracking tab's sliders: the controller's gains and believed payload
//   TeachMode         the robot at a pose of the sliders, B, C, g evaluated there
//   ExerciseMode      the student's own answers, hidden entries, checked with hints
//   ViewState         what the window shows saved as a view and restored
//   LessonMode        views strung into a lesson, presented with a clicker and notes
#include <memory>

#include <Eigen/Core>
#include <QMainWindow>
#include <QSize>
#include <QStringList>

#include "ui/document/entry_selection.hpp"
#include "ui/document/live_derivation.hpp"
#include "ui/document/live_simulation.hpp"
#include "ui/document/scene_document.hpp"
#include "ui/window/window_parts.hpp"

namespace ll::ui {

class Autosave;
class DhStepLink;
class DhStepPage;
class EditFrame;
class EntryLinking;
class ExerciseMode;
class ExportActions;
class ControlTuning;
class GhostRun;
class LanguageMenu;
class LessonMode;
class PresentationMode;
class Relabel;
class SceneFiles;
class TeachMode;
class ViewState;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Opens `path` (ui/window/scene_files.hpp: a file or a ":/examples/…" resource).
    bool openFile(const QString& path, QStringList* errors = nullptr, bool quiet = false);
    // Screenshot of the whole window, GL view included.
    QImage screenshot();
    // Whether closing with unsaved edits asks first (scripts and tests say no).
    void setAskBeforeClosing(bool on);
    // The window's size and its docks' layout as the user left them last time: restored
    // now, and saved when it closes (a user's window; screenshots and tests keep theirs).
    void rememberLayout();

    // The document and its workers.
    SceneDocument& document() { return doc_; }
    LiveSimulation& liveSimulation() { return live_; }
    LiveDerivation& liveDerivation() { return derive_; }
    EntrySelection& selection() { return selection_; }
    // The longest an edit's repaint waits for its result (100 ms; tests lengthen it so a
    // loaded machine does not decide what they see).
    void setEditHoldLimit(int milliseconds);

    // The widgets.
    ModelEditor& editor() { return *parts_.editor; }
    SceneView& sceneView() { return *parts_.view; }
    PlaybackBar& playback() { return *parts_.playback; }
    DerivationPanel& derivationPanel() { return *parts_.derivation; }
    DerivationView& derivationView() { return *parts_.typeset; }
    TrajectoryChart& energyChart() { return *parts_.energy; }
    TrajectoryChart& jointsChart() { return *parts_.joints; }
    TrajectoryChart& entryChart() { return *parts_.entryChart; }
    TeachPanel& teachPanel() { return *parts_.teach; }
    TorquePane& torquePane() { return *parts_.torques; }
    TrackingPane& trackingPane() { return *parts_.tracking; }
    PropertiesPanel& propertiesPanel() { return *parts_.properties; }
    WorkPrecisionPane& workPrecisionPane() { return *parts_.workPrecision; }
    DhStepPanel& dhStepPanel() { return *parts_.dhSteps; }
    DhStepPage& dhStepPage() { return *parts_.dhPage; }

    // The features.
    SceneFiles& files() { return *files_; }
    Autosave& autosave() { return *autosave_; }
    ExportActions& exports() { return *exports_; }
    EntryLinking& linking() { return *linking_; }
    PresentationMode& presentationMode() { return *presentationMode_; }
    LanguageMenu& language() { return *language_; }
    GhostRun& ghost() { return *ghost_; }
    ExerciseMode& exercise() { return *exercise_; }
    ExercisePanel& exercisePanel() { return *parts_.exercise; }
    ViewState& views() { return *views_; }
    LessonMode& lessons() { return *lessons_; }

    // What is on screen (null before the first result).
    const LiveResult* result() const { return shown_.result.get(); }
    const DerivationResult* derivation() const { return shown_.derived.get(); }
    const RunAnalysis* analysis() const { return shown_.analysis.get(); }
    QString statusText() const;

    // Shows step `n` 0..8 of the derivation (9: the results at the teach pose).
    void showDerivationStep(int n);
    // Teach mode at pose q: the robot posed, step 9 shows B, C, g and the energies there.
    void teach(const Eigen::VectorXd& q);
    // Shows a tab of the plots dock by name: energy, joints, teach, torques, properties,
    // work-precision, dh-steps, tracking (false: no such tab, or Tracking of a robot without a controller).
    bool showPlotTab(const QString& name);
    // Shows the derivation dock's tab: typeset, text, entries or exercise.
    void showDerivationView(const QString& name);

signals:
    // A simulation result is on screen (the 3D view, plots and playback updated).
    void resultShown(int request);

protected:
    void closeEvent(QCloseEvent* e) override;
    void dragEnterEvent(QDragEnterEvent* e) override;
    void dropEvent(QDropEvent* e) override;
    void keyPressEvent(QKeyEvent* e) override;

private:
    void buildCentre();
    void buildDocks();
    void buildFeatures();
    void buildMenus();
    void connectDocument();
    void documentChanged();
    void validSceneChanged();
    void showResult(std::shared_ptr<const LiveResult> result);
    void showDerivation(std::shared_ptr<const DerivationResult> result);
    void showAnalysis(std::shared_ptr<const RunAnalysis> analysis);
    void showTime(double t);
    void plotTabChanged(int index);
    void updateTitle();

    SceneDocument doc_;
    LiveSimulation live_;
    LiveDerivation derive_;
    EntrySelection selection_;
    WindowParts parts_;
    OnScreen shown_;
    std::shared_ptr<const DerivationResult> derivedAsDerived_;  // as the worker made it (English, the notes' notation)
    std::vector<Eigen::Vector3d> effectorPath_;                 // end effector at every sample (the trail)
    Eigen::VectorXd q_, qd_;                                    // the state shown
    Relabel* relabel_ = nullptr;                                // the window's own texts, set again when the language changes
    EditFrame* editFrame_ = nullptr;                            // one repaint per edit: the cell and its result together
    QLabel* status_ = nullptr;

    std::unique_ptr<SceneFiles> files_;
    std::unique_ptr<Autosave> autosave_;
    std::unique_ptr<ExportActions> exports_;
    std::unique_ptr<EntryLinking> linking_;
    std::unique_ptr<DhStepLink> dhStepLink_;
    std::unique_ptr<PresentationMode> presentationMode_;
    std::unique_ptr<LanguageMenu> language_;
    std::unique_ptr<GhostRun> ghost_;
    std::unique_ptr<ControlTuning> tuning_;
    std::unique_ptr<TeachMode> teachMode_;
    std::unique_ptr<ExerciseMode> exercise_;
    ViewState* views_ = nullptr;
    LessonMode* lessons_ = nullptr;

    bool remembersLayout_ = false;
    bool runFailed_ = false;   // the status line says why the newest run failed
    int shownStructure_ = -1;  // joints/coordinates of the scene on screen (a change refits the camera)
    QString shownName_;
};

}  // namespace ll::ui
