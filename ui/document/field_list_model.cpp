#include "ui/document/field_list_model.hpp"

#include <QBrush>
#include <QColor>

namespace ll::ui {

FieldListModel::FieldListModel(SceneDocument& document, FieldRows rows, QObject* parent)
    : QAbstractTableModel(parent), doc_(document), make_(std::move(rows)) {
    connect(&doc_, &SceneDocument::changed, this, &FieldListModel::documentChanged);
    connect(&doc_, &SceneDocument::validated, this, &FieldListModel::documentChanged);
    rows_ = make_(doc_.json());
}

void FieldListModel::documentChanged() {
    std::vector<FieldRow> rows = make_(doc_.json());
    const bool same =
        rows.size() == rows_.size() &&
        std::equal(rows.begin(), rows.end(), rows_.begin(), [](const FieldRow& a, const FieldRow& b) { return a.pointer == b.pointer; });
    if (!same) {
        beginResetModel();
        rows_ = std::move(rows);
        endResetModel();
    } else if (!rows_.empty()) {
        emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
    }
}

int FieldListModel::rowCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : static_cast<int>(rows_.size()); }
int FieldListModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QVariant FieldListModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid()) return {};
    const FieldRow& r = row(index.row());
    const QString error = doc_.errorAt(r.field);
    if (role == Qt::BackgroundRole && index.column() == Value) {
        if (error.startsWith("error")) return QBrush(QColor(255, 190, 190));
        if (!error.isEmpty()) return QBrush(QColor(255, 240, 190));
    }
    if (role == Qt::ToolTipRole) return error.isEmpty() ? QString::fromStdString(r.field) : error;
    if (role != Qt::DisplayRole && role != Qt::EditRole) return {};
    switch (index.column()) {
        case Name: return r.name;
        case Value: return SceneDocument::display(doc_.value(r.pointer));
        case Unit: return r.unit;
        default: return {};
    }
}

bool FieldListModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!index.isValid() || role != Qt::EditRole || index.column() != Value) return false;
    const FieldRow& r = row(index.row());
    doc_.setValue(r.pointer, SceneDocument::parseCell(value.toString()), tr("%1 = %2").arg(r.name, value.toString()));
    return true;
}

QVariant FieldListModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (role != Qt::DisplayRole || orientation != Qt::Horizontal) return {};
    switch (section) {
        case Name: return tr("field");
        case Value: return tr("value");
        case Unit: return tr("unit");
        default: return {};
    }
}

Qt::ItemFlags FieldListModel::flags(const QModelIndex& index) const {
    Qt::ItemFlags f = QAbstractTableModel::flags(index);
    if (index.column() == Value) f |= Qt::ItemIsEditable;
    return f;
}

namespace {

// The array at `pointer`, or an empty one when there is none or something else is there.
SceneJson arrayAt(const SceneJson& json, const std::string& pointer) {
    const SceneJson::json_pointer p(pointer);
    return json.contains(p) && json.at(p).is_array() ? json.at(p) : SceneJson::array();
}

bool isRevolute(const SceneJson& json, std::size_t i) {
    const SceneJson::json_pointer p("/robot/joints/" + std::to_string(i) + "/type");
    return !json.contains(p) || json.at(p) != "prismatic";
}

}  // namespace

std::vector<FieldRow> parameterRows(const SceneJson& json) {
    std::vector<FieldRow> rows;
    if (json.contains("parameters") && json["parameters"].is_object())
        for (const auto& [name, value] : json["parameters"].items())
            rows.push_back({QString::fromStdString(name), "/parameters/" + name, "parameters." + name, {}});
    return rows;
}

std::vector<FieldRow> initialStateRows(const SceneJson& json) {
    std::vector<FieldRow> rows;
    if (!json.is_object()) return rows;
    // The document may hold anything the user typed (a number for a coordinate's name, a
    // string for the joints): rows follow what is there, never throw.
    const bool lagrangian = json.contains("lagrangian");
    const SceneJson list = lagrangian ? arrayAt(json, "/lagrangian/coordinates") : arrayAt(json, "/robot/joints");
    const std::size_t n = list.size();
    auto name = [&](std::size_t i) {
        if (lagrangian) return SceneDocument::display(list[i]);
        return QString("q%1").arg(i + 1);
    };
    for (const char* key : {"q", "qd"})
        for (std::size_t i = 0; i < n; ++i) {
            const bool q = std::string(key) == "q";
            const QString unit = lagrangian ? QString() : (isRevolute(json, i) ? (q ? "rad" : "rad/s") : (q ? "m" : "m/s"));
            rows.push_back({q ? name(i) + "(0)" : name(i) + QString::fromUtf8("̇(0)"),
                            "/initial/" + std::string(key) + "/" + std::to_string(i),
                            "initial." + std::string(key) + "[" + std::to_string(i) + "]", unit});
        }
    if (json.contains("effects") && json["effects"].contains("gravity"))
        for (int i = 0; i < 3; ++i)
            rows.push_back({QString("gravity %1").arg(QChar('x' + i)), "/effects/gravity/" + std::to_string(i),
                            "effects.gravity[" + std::to_string(i) + "]", QString::fromUtf8("m/s²")});
    return rows;
}

std::vector<FieldRow> solverRows(const SceneJson&) {
    return {{"integrator", "/simulation/integrator", "simulation.integrator", {}},
            {"abs_tol", "/simulation/abs_tol", "simulation.abs_tol", {}},
            {"rel_tol", "/simulation/rel_tol", "simulation.rel_tol", {}},
            {"dt", "/simulation/dt", "simulation.dt", "s"},
            {"duration", "/simulation/duration", "simulation.duration", "s"},
            {"output_rate", "/simulation/output_rate", "simulation.output_rate", "Hz"}};
}

std::vector<FieldRow> lagrangianRows(const SceneJson& json) {
    std::vector<FieldRow> rows;
    if (!json.contains("lagrangian")) return rows;
    const SceneJson& l = json["lagrangian"];
    if (!l.is_object()) return rows;
    for (std::size_t i = 0; i < arrayAt(json, "/lagrangian/coordinates").size(); ++i)
        rows.push_back({QString("coordinate %1").arg(i + 1),
                        "/lagrangian/coordinates/" + std::to_string(i),
                        "lagrangian.coordinates[" + std::to_string(i) + "]",
                        {}});
    for (const char* key : {"kinetic", "potential"})
        if (l.contains(key)) rows.push_back({key, "/lagrangian/" + std::string(key), "lagrangian." + std::string(key), "J"});
    return rows;
}

}  // namespace ll::ui
