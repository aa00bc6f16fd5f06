#pragma once
// The DH step-through panel (step 0 of the notes): pick joint i, and frame i−1 becomes
// frame i by row i's four elementary motions (core/kinematics/dh_step_through.hpp), one
// at a time: Next/Previous move through all rows' motions, Animate carries the current
// one out over a second. Beside it: A_i as the product of the four motions, the current
// one marked with its value and unit, and A_i's numbers at the pose shown. The window
// draws the moving frame in the 3D view and marks the parameter's cell in the DH table
// (signal `stepChanged`).
#include <QTimer>
#include <QWidget>

#include "core/model/robot_model.hpp"
#include "core/kinematics/dh_step_through.hpp"

class QCheckBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace ll::ui {

class DhStepPanel : public QWidget {
    Q_OBJECT
public:
    explicit DhStepPanel(QWidget* parent = nullptr);

    // The robot (copied; a Lagrangian scene has none: the panel says so) and the pose
    // shown, whose joint value enters θ_i or d_i.
    void setRobot(const RobotModel& robot, bool isRobot);
    void setPose(const Eigen::VectorXd& q);
    // Joint (0-based) and motions done (0..4); clamped to the robot.
    void setStep(int joint, int done);
    int joint() const { return joint_; }
    int done() const { return done_; }
    double fraction() const { return fraction_; }
    // The panel's text as shown (tests): the product with the current motion marked.
    QString productText() const;
    // Whether every parameter is drawn on the robot (the static view) and to set it.
    bool showsDimensions() const;
    void setShowDimensions(bool on);

public slots:
    void next();  // the next motion, to the next row after the 4th
    void previous();
    void animate();  // carries the next motion out over one second

signals:
    // The moving frame: row joint+1 after `done` motions and `fraction` of the next.
    void stepChanged(int joint, int done, double fraction);
    // The DH table's parameter being carried out (its column), −1 for none.
    void parameterChanged(int joint, ll::DhParameter parameter);
    void dimensionsToggled(bool on);

private:
    void refresh();
    RobotModel robot_;
    bool isRobot_ = false;
    Eigen::VectorXd q_;
    int joint_ = 0, done_ = 0;
    double fraction_ = 0;
    QTimer timer_;
    QSpinBox* jointBox_;
    QLabel* product_;
    QLabel* matrix_;
    QPushButton *previous_, *next_, *animate_;
    QCheckBox* dimensions_;
};

}  // namespace ll::ui
