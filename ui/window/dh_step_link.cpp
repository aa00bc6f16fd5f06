#include "ui/window/dh_step_link.hpp"

#include <vector>

#include <QTabWidget>

#include "core/kinematics/forward_kinematics.hpp"

#include "ui/document/joint_table_model.hpp"
#include "ui/window/dh_axes_panel.hpp"
#include "ui/window/dh_step_page.hpp"
#include "ui/window/dh_step_panel.hpp"
#include "ui/window/model_editor.hpp"
#include "ui/window/playback_bar.hpp"
#include "ui/window/scene_view.hpp"

namespace ll::ui {

DhStepLink::DhStepLink(const WindowParts& parts) : parts_(parts) {
    DhStepPanel* panel = parts.dhSteps;
    connect(panel, &DhStepPanel::stepChanged, this, [this](int joint, int done, double fraction) {
        if (shown()) parts_.view->setDhStep(joint, done, fraction);
    });
    connect(panel, &DhStepPanel::parameterChanged, this, [this](int joint, DhParameter parameter) {
        if (!shown()) return;
        const int column = parameter == DhParameter::A       ? JointTableModel::A
                           : parameter == DhParameter::Alpha ? JointTableModel::Alpha
                           : parameter == DhParameter::D     ? JointTableModel::D
                                                             : JointTableModel::Theta;
        parts_.editor->markDhParameter(joint, column);
    });
    connect(panel, &DhStepPanel::dimensionsToggled, this, [this](bool on) { parts_.view->setShowDimensions(on && shown()); });
    connect(parts.dhAxes, &DhAxesPanel::stepChanged, this, [this] {
        if (holding_) parts_.view->setConstruction(parts_.dhAxes->marks());
    });
    connect(parts.plotTabs, &QTabWidget::currentChanged, this, &DhStepLink::pageChanged);
    connect(parts.dhPage, &QTabWidget::currentChanged, this, &DhStepLink::pageChanged);
}

void DhStepLink::pageChanged() {
    parts_.view->setShowDimensions(shown() && parts_.dhSteps->showsDimensions());
    if (shown()) {
        parts_.dhSteps->setPose(parts_.view->shownPose());
        parts_.dhSteps->setStep(parts_.dhSteps->joint(), parts_.dhSteps->done());  // marks the table, draws the frame
    } else {
        parts_.view->setDhStep(-1, 0, 0);
    }
    const bool hold = holdsHome();
    if (hold) {
        // The rules start from the robot at home; its own frames give way to the marks.
        parts_.playback->pause();
        showHome();
        parts_.view->setConstruction(parts_.dhAxes->marks());
    } else if (holding_) {
        parts_.view->setConstruction({});
    }
    const bool released = holding_ && !hold;
    holding_ = hold;
    if (released) emit homeReleased();
}

void DhStepLink::showHome() {
    static const std::vector<Eigen::Vector3d> noTrail;
    parts_.view->setPose(Eigen::VectorXd::Zero(dof_), parts_.playback->time(), &noTrail);
}

bool DhStepLink::shown() const { return parts_.plotTabs->currentWidget() == parts_.dhPage && parts_.dhPage->currentWidget() == parts_.dhSteps; }

bool DhStepLink::holdsHome() const {
    return dof_ > 0 && parts_.plotTabs->currentWidget() == parts_.dhPage && parts_.dhPage->currentWidget() == parts_.dhAxes;
}

void DhStepLink::sceneChanged(const Scene& scene) {
    dof_ = scene.lagrangian ? 0 : scene.robot.dof();
    parts_.dhSteps->setRobot(scene.robot, !scene.lagrangian);
    // A URDF's link frames where they stand at home, drawn over the frames the rules find.
    std::vector<std::pair<std::string, Eigen::Isometry3d>> overlay;
    if (dof_ > 0 && !scene.robot.links.empty()) {
        RobotData data(scene.robot);
        forwardKinematics(scene.robot, data, Eigen::VectorXd::Zero(dof_));
        for (const LinkVisual& link : scene.robot.links)
            if (link.body >= 0 && link.body <= dof_)
                overlay.emplace_back(link.name, link.body == 0 ? link.frame : data.T_0i[static_cast<std::size_t>(link.body)] * link.frame);
    }
    parts_.dhAxes->setRobot(scene.robot, !scene.lagrangian, std::move(overlay));
    pageChanged();
}

void DhStepLink::poseShown(const Eigen::VectorXd& q) {
    if (shown()) parts_.dhSteps->setPose(q);
}

}  // namespace ll::ui
