#pragma once
// Re-simulation after every valid edit, off the GUI thread: request(scene) restarts a
// short debounce; when it fires the newest scene is copied to a worker, the previous
// worker's run is cancelled (its cancel flag set, its result dropped), and the worker
// simulates it and builds its VisualScene (fitted to the motion). The result comes
// back through a queued call as plain data owned by the receiver; results older than
// the newest request are discarded, so the newest edit always wins.
#include <atomic>
#include <memory>
#include <optional>
#include <string>

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include "core/model/scene.hpp"
#include "core/visual/visual_scene.hpp"
#include "core/simulation/control_history.hpp"
#include "core/simulation/model_properties.hpp"
#include "core/simulation/torque_parts.hpp"
#include "core/simulation/trajectory.hpp"
#include "ui/document/newest_wins.hpp"
#include "ui/document/work_pool.hpp"

namespace ll::ui {

struct LiveResult {
    int request = 0;                     // which request this answers
    std::shared_ptr<const Scene> scene;  // the scene simulated
    SimulationResult simulation;
    std::shared_ptr<VisualScene> visual;  // posed at the last sample; fitted to the motion
    std::string error;                    // why there is no trajectory (empty when there is)
    double workerSeconds = 0.0;           // wall time in the worker
};

// What the run says about the model, computed after the run is shown (same worker):
// where the torque goes (core/simulation/torque_parts) and the model's properties along
// it (core/simulation/model_properties); for a controlled robot what its controller did
// (core/simulation/control_history).
struct RunAnalysis {
    int request = 0;                               // the LiveResult it belongs to
    std::shared_ptr<const TorqueHistory> torques;  // null when it could not be computed
    std::shared_ptr<const ModelProperties> properties;
    std::shared_ptr<const ControlHistory> control;  // null without a controller
    std::string error;  // why not
};

class LiveSimulation : public QObject {
    Q_OBJECT
public:
    explicit LiveSimulation(QObject* parent = nullptr);
    ~LiveSimulation() override;

    // Settings used instead of the scene's own (e.g. a ghost run with another integrator);
    // unset: the scene's.
    void setSettingsOverride(std::optional<SimulationSettings> settings) { override_ = std::move(settings); }
    void setDebounce(int milliseconds) { debounce_.setInterval(milliseconds); }
    // Also analyse each run (RunAnalysis, signal analysed), after its result is delivered.
    void setAnalysing(bool on) { analysing_ = on; }
    // Simulates `scene` (copied): at once after a pause, else after the debounce; a newer
    // request replaces it.
    void request(const Scene& scene);
    // Starts now, without the debounce.
    void requestNow(const Scene& scene);
    int latestRequest() const { return work_.newest(); }
    bool busy() const { return delivered_ < work_.newest(); }
    // Blocks until every worker has finished (tests, shutdown).
    void wait() { pool_.waitForDone(); }

signals:
    void finished(std::shared_ptr<const ll::ui::LiveResult> result);
    void analysed(std::shared_ptr<const ll::ui::RunAnalysis> analysis);

private:
    void start();
    QTimer debounce_;
    QElapsedTimer lastStart_;  // since the last run started (the debounce's leading edge)
    WorkPool pool_;
    std::shared_ptr<const Scene> pending_;
    std::optional<SimulationSettings> override_;
    NewestWins work_;
    int delivered_ = 0;
    bool analysing_ = false;
};

}  // namespace ll::ui
