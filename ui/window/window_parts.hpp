#pragma once
// What the window's features share: the widgets MainWindow builds (a feature links the
// ones it needs and builds none of them) and what is on screen now (the run, its sampler,
// the derivation as shown). MainWindow owns both; the features read them.
#include <memory>
#include <vector>

#include "core/visual/trajectory_sampler.hpp"
#include "ui/document/live_derivation.hpp"
#include "ui/document/live_simulation.hpp"

class QDockWidget;
class QLabel;
class QMainWindow;
class QTabWidget;
class QWidget;

namespace ll::ui {

class DerivationPanel;
class DerivationView;
class DhAxesPanel;
class DhStepPage;
class DhStepPanel;
class ExercisePanel;
class ModelEditor;
class PlaybackBar;
class PropertiesPanel;
class SceneView;
class TeachPanel;
class TorquePane;
class TrackingPane;
class TrajectoryChart;
class WorkPrecisionPane;

// The run and the derivation on screen; replaced whole when a newer one arrives.
struct OnScreen {
    std::shared_ptr<const LiveResult> result;         // the run shown (null before the first)
    std::unique_ptr<TrajectorySampler> sampler;       // over result's trajectory
    std::shared_ptr<const DerivationResult> derived;  // as shown: in the chosen language and notation
    std::shared_ptr<const RunAnalysis> analysis;      // torques and properties of `result`, once they arrive
    std::vector<int> litLinks;                        // 1-based: the links an exercise's hint names (lit when nothing is picked)
};

struct WindowParts {
    QMainWindow* window = nullptr;
    QDockWidget *modelDock = nullptr, *derivationDock = nullptr, *plotDock = nullptr;
    ModelEditor* editor = nullptr;  // the model dock's tabs and checks
    SceneView* view = nullptr;      // the 3D view
    PlaybackBar* playback = nullptr;
    QLabel* readout = nullptr;              // the picked entry's value, under the 3D view
    DerivationPanel* derivation = nullptr;  // the derivation as text
    DerivationView* typeset = nullptr;      // the derivation typeset
    QTabWidget* derivationTabs = nullptr;   // typeset, text, entries, exercise
    ExercisePanel* exercise = nullptr;      // the exercise tab (ui/window/exercise_mode)
    QTabWidget* plotTabs = nullptr;         // the plots dock's tabs
    QWidget* energyPage = nullptr;          // the energy plot with the picked entry's plot beside it
    TrajectoryChart *energy = nullptr, *joints = nullptr, *entryChart = nullptr;
    TeachPanel* teach = nullptr;
    TorquePane* torques = nullptr;
    TrackingPane* tracking = nullptr;  // a controlled robot's (ui/window/tracking_pane)
    PropertiesPanel* properties = nullptr;
    WorkPrecisionPane* workPrecision = nullptr;
    DhStepPage* dhPage = nullptr;    // the DH step-through tab: its two pages below
    DhStepPanel* dhSteps = nullptr;  // row by row
    DhAxesPanel* dhAxes = nullptr;   // find the DH parameters
};

}  // namespace ll::ui
