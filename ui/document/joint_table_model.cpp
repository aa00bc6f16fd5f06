#include "ui/document/joint_table_model.hpp"
#include <map>

#include <cmath>
#include <numbers>

#include <QBrush>
#include <QColor>
#include <QPixmap>

#include "core/visual/link_colors.hpp"
#include "core/model/diagnostics.hpp"

namespace ll::ui {

namespace {

const char* const kKeys[] = {"type", "a", "alpha", "d", "theta", "mass", "com", "com", "com", "xx", "yy", "zz", "xy", "xz", "yz"};

bool isAngle(int column) { return column == JointTableModel::Alpha || column == JointTableModel::Theta; }

// Default values the loader uses for absent fields (shown greyed).
SceneJson absentValue(int column) { return column == JointTableModel::Type ? SceneJson("revolute") : SceneJson(0); }

}  // namespace

JointTableModel::JointTableModel(SceneDocument& document, QObject* parent) : QAbstractTableModel(parent), doc_(document) {
    connect(&doc_, &SceneDocument::changed, this, &JointTableModel::documentChanged);
    connect(&doc_, &SceneDocument::validated, this, &JointTableModel::documentChanged);
    documentChanged();
}

void JointTableModel::documentChanged() {
    const SceneJson joints = doc_.value("/robot/joints");
    const int rows = joints.is_array() ? static_cast<int>(joints.size()) : 0;
    if (rows != rows_) {
        beginResetModel();
        rows_ = rows;
        endResetModel();
    } else if (rows_ > 0) {
        emit dataChanged(index(0, 0), index(rows_ - 1, ColumnCount - 1));
    }
}

int JointTableModel::rowCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : rows_; }
int JointTableModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

std::string JointTableModel::pointer(int row, int column) {
    std::string p = "/robot/joints/" + std::to_string(row) + "/";
    if (column >= ComX && column <= ComZ) return p + "com/" + std::to_string(column - ComX);
    if (column >= Ixx) return p + "inertia/" + kKeys[column];
    return p + kKeys[column];
}

std::string JointTableModel::fieldPath(int row, int column) {
    if (column >= ComX && column <= ComZ) return jointField(row, "com[" + std::to_string(column - ComX) + "]");
    if (column >= Ixx) return jointField(row, std::string("inertia.") + kKeys[column]);
    return jointField(row, kKeys[column]);
}

QVariant JointTableModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid()) return {};
    const int row = index.row(), column = index.column();
    const SceneJson v = doc_.value(pointer(row, column));
    const QString error = doc_.errorAt(fieldPath(row, column));
    switch (role) {
        case Qt::DisplayRole:
        case Qt::EditRole: {
            const SceneJson shown = v.is_null() ? absentValue(column) : v;
            if (degrees_ && isAngle(column) && shown.is_number()) {
                const double deg = shown.get<double>() * 180.0 / std::numbers::pi;
                return QString::number(deg, 'g', 10) + QStringLiteral("°");
            }
            // The joint's kind in the window's language; the scene file's word when edited.
            if (role == Qt::DisplayRole && column == Type && shown.is_string()) {
                if (shown.get<std::string>() == "revolute") return tr("revolute");
                if (shown.get<std::string>() == "prismatic") return tr("prismatic");
            }
            return SceneDocument::display(shown);
        }
        case Qt::ToolTipRole:
            if (!error.isEmpty()) return error;
            return QString::fromStdString(fieldPath(row, column));
        case Qt::BackgroundRole:
            if (error.startsWith("error")) return QBrush(QColor(255, 190, 190));
            if (!error.isEmpty()) return QBrush(QColor(255, 240, 190));
            return {};
        case Qt::ForegroundRole:
            if (v.is_null()) return QBrush(QColor(140, 140, 140));
            return {};
        default: return {};
    }
}

bool JointTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!index.isValid() || role != Qt::EditRole) return false;
    const int row = index.row(), column = index.column();
    QString text = value.toString().trimmed();
    SceneJson v = SceneDocument::parseCell(text);
    if (degrees_ && isAngle(column) && v.is_number()) v = text.toStdString() + "°";
    if (column == Type) v = text.toLower().toStdString();
    const QString what = headerData(column, Qt::Horizontal, Qt::DisplayRole).toString();
    // Absent array entries (a COM without all three) are filled with zeros first.
    if (column >= ComX && column <= ComZ && !doc_.value("/robot/joints/" + std::to_string(row) + "/com").is_array()) {
        SceneJson after = doc_.json();
        after["robot"]["joints"][row]["com"] = SceneJson::array({0, 0, 0});
        after["robot"]["joints"][row]["com"][column - ComX] = v;
        doc_.replace(after, tr("Joint %1: %2 = %3").arg(row + 1).arg(what, text));
        return true;
    }
    doc_.setValue(pointer(row, column), v, tr("Joint %1: %2 = %3").arg(row + 1).arg(what, text));
    return true;
}

QVariant JointTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation == Qt::Vertical && role == Qt::DecorationRole) {
        // the row's link in its colour, as in the 3D view and on its symbols in the formulas
        const Rgba c = linkColor(section);
        QPixmap swatch(12, 12);
        swatch.fill(QColor(int(c.r * 255), int(c.g * 255), int(c.b * 255)));
        return swatch;
    }
    if (role != Qt::DisplayRole) return {};
    if (orientation == Qt::Vertical) return tr("joint %1").arg(section + 1);
    const QString angle = degrees_ ? tr("[°]") : tr("[rad]");
    switch (section) {
        case Type: return tr("type");
        case A: return tr("a [m]");
        case Alpha: return tr("α %1").arg(angle);
        case D: return tr("d [m]");
        case Theta: return tr("θ offset %1").arg(angle);
        case Mass: return tr("mass [kg]");
        case ComX: return tr("COM x [m]");
        case ComY: return tr("COM y [m]");
        case ComZ: return tr("COM z [m]");
        case Ixx: return tr("Ixx [kg·m²]");
        case Iyy: return tr("Iyy [kg·m²]");
        case Izz: return tr("Izz [kg·m²]");
        case Ixy: return tr("Ixy [kg·m²]");
        case Ixz: return tr("Ixz [kg·m²]");
        case Iyz: return tr("Iyz [kg·m²]");
        default: return {};
    }
}

Qt::ItemFlags JointTableModel::flags(const QModelIndex& index) const { return QAbstractTableModel::flags(index) | Qt::ItemIsEditable; }

void JointTableModel::relabel() {
    emit headerDataChanged(Qt::Horizontal, 0, columnCount() - 1);
    if (rows_ > 0) {
        emit headerDataChanged(Qt::Vertical, 0, rows_ - 1);
        emit dataChanged(index(0, 0), index(rows_ - 1, columnCount() - 1));
    }
}

void JointTableModel::setDegrees(bool on) {
    if (on == degrees_) return;
    degrees_ = on;
    emit headerDataChanged(Qt::Horizontal, Alpha, Theta);
    if (rows_ > 0) emit dataChanged(index(0, Alpha), index(rows_ - 1, Theta));
}

namespace {

// The initial-state arrays follow the joints: `edit` is applied to q and q̇ alike.
template <class F>
void editInitial(SceneJson& json, F&& edit) {
    for (const char* key : {"q", "qd"})
        if (json.contains("initial") && json["initial"].contains(key) && json["initial"][key].is_array()) edit(json["initial"][key]);
}

}  // namespace

void JointTableModel::addJoint(int after) {
    SceneJson json = doc_.json();
    SceneJson& joints = json["robot"]["joints"];
    if (!joints.is_array()) joints = SceneJson::array();
    const int n = static_cast<int>(joints.size());
    const int at = std::clamp(after, -1, n - 1) + 1;
    SceneJson joint = n > 0 ? joints[std::max(at - 1, 0)] : SceneJson{{"type", "revolute"}, {"a", 0.5},  {"alpha", 0},          {"d", 0},
                                                                      {"theta", 0},         {"mass", 1}, {"com", {-0.25, 0, 0}}};
    joints.insert(joints.begin() + at, joint);
    editInitial(json, [&](SceneJson& a) {
        if (static_cast<int>(a.size()) >= at) a.insert(a.begin() + at, 0);
    });
    doc_.replace(json, tr("Add joint %1").arg(at + 1));
}

void JointTableModel::removeJoint(int row) {
    SceneJson json = doc_.json();
    SceneJson& joints = json["robot"]["joints"];
    if (!joints.is_array() || row < 0 || row >= static_cast<int>(joints.size())) return;
    joints.erase(joints.begin() + row);
    editInitial(json, [&](SceneJson& a) {
        if (row < static_cast<int>(a.size())) a.erase(a.begin() + row);
    });
    doc_.replace(json, tr("Remove joint %1").arg(row + 1));
}

void JointTableModel::moveJoint(int row, int delta) {
    SceneJson json = doc_.json();
    SceneJson& joints = json["robot"]["joints"];
    const int other = row + delta;
    if (!joints.is_array() || row < 0 || other < 0 || row >= static_cast<int>(joints.size()) || other >= static_cast<int>(joints.size()))
        return;
    std::swap(joints[row], joints[other]);
    editInitial(json, [&](SceneJson& a) {
        if (std::max(row, other) < static_cast<int>(a.size())) std::swap(a[row], a[other]);
    });
    doc_.replace(json, tr("Move joint %1 to %2").arg(row + 1).arg(other + 1));
}

bool JointTableModel::fillInertiaFromShape(int row, const QString& shape, const QStringList& dims) {
    const SceneJson massJson = doc_.value("/robot/joints/" + std::to_string(row) + "/mass");
    const QString m = "(" + (massJson.is_null() ? QString("0") : SceneDocument::display(massJson)) + ")";
    auto d = [&](int i) { return "(" + (i < dims.size() ? dims[i].trimmed() : QString("0")) + ")"; };
    QString xx = "0", yy = "0", zz = "0";
    const QString s = shape.toLower();
    if (s == "rod" && dims.size() >= 1) {
        yy = zz = m + "*" + d(0) + "^2/12";
    } else if (s == "cylinder" && dims.size() >= 2) {
        zz = m + "*" + d(0) + "^2/2";
        xx = yy = m + "*(3*" + d(0) + "^2+" + d(1) + "^2)/12";
    } else if (s == "disc" && dims.size() >= 1) {
        zz = m + "*" + d(0) + "^2/2";
        xx = yy = m + "*" + d(0) + "^2/4";
    } else if (s == "box" && dims.size() >= 3) {
        xx = m + "*(" + d(1) + "^2+" + d(2) + "^2)/12";
        yy = m + "*(" + d(0) + "^2+" + d(2) + "^2)/12";
        zz = m + "*(" + d(0) + "^2+" + d(1) + "^2)/12";
    } else if (s == "sphere" && dims.size() >= 1) {
        xx = yy = zz = "2*" + m + "*" + d(0) + "^2/5";
    } else {
        return false;
    }
    SceneJson json = doc_.json();
    json["robot"]["joints"][row]["inertia"] = {{"xx", SceneDocument::parseCell(xx)},
                                               {"yy", SceneDocument::parseCell(yy)},
                                               {"zz", SceneDocument::parseCell(zz)},
                                               {"xy", 0},
                                               {"xz", 0},
                                               {"yz", 0}};
    static const std::map<QString, const char*> shapeNames = {{"rod", QT_TR_NOOP("rod")},
                                                              {"cylinder", QT_TR_NOOP("cylinder")},
                                                              {"disc", QT_TR_NOOP("disc")},
                                                              {"box", QT_TR_NOOP("box")},
                                                              {"sphere", QT_TR_NOOP("sphere")}};
    const auto named = shapeNames.find(shape);
    doc_.replace(json, tr("Joint %1: inertia of a %2").arg(row + 1).arg(named != shapeNames.end() ? tr(named->second) : shape));
    return true;
}

}  // namespace ll::ui
