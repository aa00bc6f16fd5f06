#include "ui/window/dh_step_link.hpp"

#include <QTabWidget>

#include "ui/document/joint_table_model.hpp"
#include "ui/window/dh_step_panel.hpp"
#include "ui/window/model_editor.hpp"
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
    connect(parts.plotTabs, &QTabWidget::currentChanged, this, [this] {
        parts_.view->setShowDimensions(shown() && parts_.dhSteps->showsDimensions());
        if (shown()) {
            parts_.dhSteps->setPose(parts_.view->shownPose());
            parts_.dhSteps->setStep(parts_.dhSteps->joint(), parts_.dhSteps->done());  // marks the table, draws the frame
        } else {
            parts_.view->setDhStep(-1, 0, 0);
        }
    });
}

bool DhStepLink::shown() const { return parts_.plotTabs->currentWidget() == parts_.dhSteps; }

void DhStepLink::poseShown(const Eigen::VectorXd& q) {
    if (shown()) parts_.dhSteps->setPose(q);
}

}  // namespace ll::ui
