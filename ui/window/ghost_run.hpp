#pragma once
// Simulation → Ghost run: the same scene run again with a cheaper integrator (a fixed-step
// method of the catalogue at dt = 0.01 s, or dopri5 at a loose tolerance), drawn as a
// translucent robot beside the real one and as a second energy curve, so a student sees
// what the cheaper method costs in accuracy. Without one, a robot with a controller shows
// its reference q_d(t) as the ghost instead: where the controller wants the robot to be.
#include <memory>
#include <optional>

#include <Eigen/Core>
#include <QObject>
#include <QString>

#include "core/model/control.hpp"
#include "ui/window/window_parts.hpp"

class QMenu;

namespace ll::ui {

class SceneDocument;

class GhostRun : public QObject {
    Q_OBJECT
public:
    GhostRun(const SceneDocument& document, const WindowParts& parts);

    // The menu's entries: none, every fixed-step integrator of core's catalogue, dopri5 1e-3.
    void addTo(QMenu* simulation);
    // Runs a ghost of the valid scene with `integrator` ("" removes it; "NAME TOL" sets
    // both tolerances).
    void setIntegrator(const QString& integrator);
    const QString& integrator() const { return integrator_; }
    // The valid scene changed: the ghost follows.
    void sceneChanged(const Scene& scene);
    // The real run was replaced: the energy plot shows the ghost's curve again; without a
    // ghost run, a controlled robot's reference becomes the ghost.
    void runShown(const LiveResult& shown);
    // The reference's ghost is shown (a controlled robot, no ghost run).
    bool showsReference() const { return reference_.has_value(); }
    // The ghost's pose at time t.
    void showAt(double t);
    const LiveResult* result() const { return result_.get(); }

signals:
    // A ghost run arrived: the window poses it at the time shown.
    void shown();

private:
    void show(std::shared_ptr<const LiveResult> result);

    const SceneDocument& doc_;
    const WindowParts& parts_;
    LiveSimulation live_;
    QString integrator_;
    std::shared_ptr<const LiveResult> result_;
    std::unique_ptr<TrajectorySampler> sampler_;
    std::optional<ControlReference> reference_;  // the controller's q_d(t), drawn when no ghost run is
    std::shared_ptr<VisualScene> referenceVisual_;
    Eigen::VectorXd qRef_, qdRef_, qddRef_;
};

}  // namespace ll::ui
