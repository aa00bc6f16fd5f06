#pragma once
// A Qt item model over a finished simulation: one row per sample, columns t, q_i,
// q̇_i, E_kin, E_pot, E, W. Coordinates are headed by Trajectory::names as the
// derivation's text prints them (q1, q̇1; a Lagrangian system's theta1 as θ1, θ̇1). The GUI's table and plots read the trajectory through it
// (one model, several views); it owns an immutable copy, never live solver state.
#include <QAbstractTableModel>

#include "core/simulation/trajectory.hpp"

namespace ll::ui {

class TrajectoryTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    explicit TrajectoryTableModel(QObject* parent = nullptr);

    void setTrajectory(Trajectory trajectory);
    const Trajectory& trajectory() const { return trajectory_; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    double value(int row, int column) const;
    Trajectory trajectory_;
};

}  // namespace ll::ui
