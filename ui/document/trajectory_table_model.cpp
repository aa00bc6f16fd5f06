#include "ui/document/trajectory_table_model.hpp"

#include "core/present/expression_printer.hpp"

namespace ll::ui {

TrajectoryTableModel::TrajectoryTableModel(QObject* parent) : QAbstractTableModel(parent) {}

void TrajectoryTableModel::setTrajectory(Trajectory trajectory) {
    beginResetModel();
    trajectory_ = std::move(trajectory);
    endResetModel();
}

int TrajectoryTableModel::rowCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : static_cast<int>(trajectory_.size()); }

int TrajectoryTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() || trajectory_.size() == 0 ? 0 : 1 + 2 * trajectory_.n + 4;
}

double TrajectoryTableModel::value(int row, int column) const {
    const int n = trajectory_.n;
    if (column == 0) return trajectory_.t[row];
    if (column <= n) return trajectory_.q[row][column - 1];
    if (column <= 2 * n) return trajectory_.qd[row][column - 1 - n];
    switch (column - 2 * n) {
        case 1: return trajectory_.Ekin[row];
        case 2: return trajectory_.Epot[row];
        case 3: return trajectory_.E[row];
        default: return trajectory_.work[row];
    }
}

QVariant TrajectoryTableModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount() || index.column() >= columnCount()) return {};
    if (role == Qt::DisplayRole) return QString::number(value(index.row(), index.column()), 'g', 6);
    if (role == Qt::EditRole || role == Qt::UserRole) return value(index.row(), index.column());
    return {};
}

QVariant TrajectoryTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (role != Qt::DisplayRole) return {};
    if (orientation == Qt::Vertical) return section + 1;
    const int n = trajectory_.n;
    if (section == 0) return QStringLiteral("t [s]");
    if (section <= 2 * n) {
        const int i = (section - 1) % n;
        return QString::fromStdString(present::textCoordinateName(trajectory_.coordinateName(i), section > n ? 1 : 0));
    }
    static const char* energies[] = {"E_kin [J]", "E_pot [J]", "E [J]", "W [J]"};
    const int k = section - 2 * n - 1;
    return k < 4 ? QVariant(QString::fromUtf8(energies[k])) : QVariant();
}

}  // namespace ll::ui
