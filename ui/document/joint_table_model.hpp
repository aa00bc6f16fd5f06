#pragma once
// The robot's joints as an editable table over a SceneDocument: the DH columns (type,
// a, α, d, θ offset) and the link inertials (mass, COM, inertia tensor) of one joint
// per row, as typed (numbers or parameter expressions). Every edit is one undoable
// command of the document; a cell whose field has an error (the loader's or
// checkScene's message naming robot.joints[i].field) is drawn red with the message as
// its tooltip. Angles are shown in radians or, with setDegrees(true), numbers in
// degrees ("90°"); a number typed in degree mode is stored as degrees.
#include <string>

#include <QAbstractTableModel>

#include "ui/document/scene_document.hpp"

namespace ll::ui {

class JointTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Type, A, Alpha, D, Theta, Mass, ComX, ComY, ComZ, Ixx, Iyy, Izz, Ixy, Ixz, Iyz, ColumnCount };
    static constexpr int firstDhColumn = Type, lastDhColumn = Theta;
    static constexpr int firstInertialColumn = Mass, lastInertialColumn = Iyz;

    explicit JointTableModel(SceneDocument& document, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;

    bool degrees() const { return degrees_; }
    void setDegrees(bool on);
    // The language changed: every header and cell is text again (the views size to it).
    void relabel();

    // Undoable edits of the joint list (initial q and q̇ follow the joints).
    void addJoint(int after);  // a copy of joint `after` (a revolute joint when none)
    void removeJoint(int row);
    void moveJoint(int row, int delta);
    // Fills the inertia tensor of joint `row` from a shape of mass m (its current mass)
    // along the link's x axis (rod, box) or z axis (cylinder, disc):
    //   rod length L:        Iyy = Izz = m L²/12
    //   cylinder r, h:       Izz = m r²/2, Ixx = Iyy = m(3r² + h²)/12
    //   disc r:              Izz = m r²/2, Ixx = Iyy = m r²/4
    //   box x, y, z:         Ixx = m(y² + z²)/12, …
    //   sphere r:            Ixx = Iyy = Izz = 2 m r²/5
    // `dims` as the user types them (numbers or expressions of the parameters); the
    // entries are written as expressions of them. Returns false for an unknown shape.
    bool fillInertiaFromShape(int row, const QString& shape, const QStringList& dims);

    // The JSON pointer and the loader's field path of a cell.
    static std::string pointer(int row, int column);
    static std::string fieldPath(int row, int column);

private:
    void documentChanged();
    SceneDocument& doc_;
    int rows_ = 0;
    bool degrees_ = false;
};

}  // namespace ll::ui
