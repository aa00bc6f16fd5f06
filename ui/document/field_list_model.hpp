#pragma once
// A list of named scene fields (name, value as typed, unit) over a SceneDocument, for the
// editor's smaller tabs: parameters, initial q and q̇, gravity, the integrator and its
// tolerances, a Lagrangian's coordinates and expressions. Which fields it lists comes
// from a function of the JSON, so the rows follow the document (a new joint adds its
// q and q̇). Every edit is one undoable command; a field with an error is red with the
// message as its tooltip.
#include <functional>
#include <string>
#include <vector>

#include <QAbstractTableModel>

#include "ui/document/scene_document.hpp"

namespace ll::ui {

struct FieldRow {
    QString name;         // shown, e.g. "q1", "abs_tol"
    std::string pointer;  // JSON pointer, e.g. "/initial/q/0"
    std::string field;    // the loader's field path, e.g. "initial.q[1]"
    QString unit;         // e.g. "rad", "m/s²"
};

using FieldRows = std::function<std::vector<FieldRow>(const SceneJson&)>;

class FieldListModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Name, Value, Unit, ColumnCount };
    FieldListModel(SceneDocument& document, FieldRows rows, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;

    const FieldRow& row(int i) const { return rows_[static_cast<std::size_t>(i)]; }

private:
    void documentChanged();
    SceneDocument& doc_;
    FieldRows make_;
    std::vector<FieldRow> rows_;
};

// The rows of the editor's tabs.
std::vector<FieldRow> parameterRows(const SceneJson& json);
std::vector<FieldRow> initialStateRows(const SceneJson& json);  // q, q̇, gravity
std::vector<FieldRow> solverRows(const SceneJson& json);        // integrator, tolerances, duration
std::vector<FieldRow> lagrangianRows(const SceneJson& json);    // coordinates, E_kin, E_pot

}  // namespace ll::ui
