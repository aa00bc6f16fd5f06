#pragma once
// The "Torques" tab: for one joint at a time, the terms of B q̈ + C q̇ + g = Q along the
// run (core/simulation/torque_parts) as curves with the playback cursor: inertial B q̈,
// Coriolis/centrifugal C q̇, gravity and springs g, and Q split into actuation, viscous and
// Coulomb friction (the parts a scene does not declare are left out), in the joint's unit.
#include <memory>

#include <QWidget>

#include "core/model/scene.hpp"
#include "core/simulation/torque_parts.hpp"

class QComboBox;
class QLabel;

namespace ll::ui {

class TrajectoryChart;

class TorquePane : public QWidget {
    Q_OBJECT
public:
    explicit TorquePane(QWidget* parent = nullptr);

    // The parts of a run of `scene`; null history: none yet.
    void setTorques(std::shared_ptr<const TorqueHistory> history, std::shared_ptr<const Scene> scene);
    void setJoint(int joint);  // 0-based
    int joint() const;
    void setCursorTime(double t);
    TrajectoryChart& chart() { return *chart_; }

signals:
    void timePicked(double t);

private:
    void redraw();

    std::shared_ptr<const TorqueHistory> history_;
    std::shared_ptr<const Scene> scene_;
    QComboBox* joint_;
    QLabel* residual_;
    TrajectoryChart* chart_;
};

}  // namespace ll::ui
