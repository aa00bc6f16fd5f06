#include "ui/window/teach_mode.hpp"

#include <memory>
#include <vector>

#include <QTabWidget>

#include "core/pipeline/pose_results.hpp"
#include "ui/document/entry_selection.hpp"
#include "ui/document/scene_document.hpp"
#include "ui/window/derivation_view.hpp"
#include "ui/window/dh_step_link.hpp"
#include "ui/window/playback_bar.hpp"
#include "ui/window/scene_view.hpp"
#include "ui/window/teach_panel.hpp"

namespace ll::ui {

TeachMode::TeachMode(const SceneDocument& document, EntrySelection& selection, DhStepLink& dhSteps, const WindowParts& parts)
    : doc_(document), selection_(selection), dhSteps_(dhSteps), parts_(parts) {
    connect(parts.playback, &PlaybackBar::playingChanged, this, [this](bool playing) {
        if (!playing) return;
        active_ = false;
        updatePoseResults();  // the pose step goes with teach mode
    });
    connect(parts.teach, &TeachPanel::poseChanged, this, [this](const Eigen::VectorXd& q) {
        if (!active_) return;
        showPose(q);
        updatePoseResults();
    });
}

bool TeachMode::tabShown(int index) {
    active_ = parts_.plotTabs->widget(index) == parts_.teach;
    updatePoseResults();
    if (active_) {
        parts_.playback->pause();
        showPose(parts_.teach->pose());
    }
    return active_;
}

void TeachMode::teach(const Eigen::VectorXd& q) {
    parts_.plotTabs->setCurrentWidget(parts_.teach);
    parts_.teach->setPose(q);
    showPose(parts_.teach->pose());
}

// The robot at a teach pose, without the trail of the motion (which is not where it is).
void TeachMode::showPose(const Eigen::VectorXd& q) {
    static const std::vector<Eigen::Vector3d> noTrail;
    parts_.view->setPose(q, parts_.playback->time(), &noTrail);
    dhSteps_.poseShown(q);
    // The picked entry at the pose, the joints at rest (as the pose results take them).
    const Scene& scene = doc_.validScene();
    const int n = static_cast<int>(q.size());
    selection_.setState(q, scene.initial.qd.size() == n ? scene.initial.qd : Eigen::VectorXd::Zero(n), parts_.playback->time(), true);
}

// Step 9 of the typeset derivation while teaching: B, C, g and the energies at the pose.
void TeachMode::updatePoseResults() {
    const Scene& scene = doc_.validScene();
    const int n = scene.robot.dof();
    if (!active_ || scene.lagrangian || n == 0 || parts_.teach->pose().size() != n) {
        parts_.typeset->setPoseResults(nullptr);
        return;
    }
    const Eigen::VectorXd qd = scene.initial.qd.size() == n ? scene.initial.qd : Eigen::VectorXd::Zero(n);
    parts_.typeset->setPoseResults(std::make_shared<const present::DisplayStep>(poseResults(scene, parts_.teach->pose(), qd)));
}

}  // namespace ll::ui
