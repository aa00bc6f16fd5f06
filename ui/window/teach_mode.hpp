#pragma once
// Teach mode: while the Teach tab is shown, the robot stands at the pose its sliders set
// (not where the motion is), the derivation's step 9 shows B, C, g and the energies
// evaluated there, and the picked entry takes its value at the pose. Playing, or another
// tab, ends it.
#include <Eigen/Core>
#include <QObject>

#include "ui/window/window_parts.hpp"

namespace ll::ui {

class DhStepLink;
class EntrySelection;
class SceneDocument;

class TeachMode : public QObject {
    Q_OBJECT
public:
    TeachMode(const SceneDocument& document, EntrySelection& selection, DhStepLink& dhSteps, const WindowParts& parts);

    bool active() const { return active_; }
    // The plots dock shows tab `index`: teach mode is on while it is the Teach tab (true then).
    bool tabShown(int index);
    // Teach mode at pose q, the Teach tab brought to the front.
    void teach(const Eigen::VectorXd& q);
    // The scene changed: the results at the pose follow.
    void sceneChanged() { updatePoseResults(); }

private:
    void showPose(const Eigen::VectorXd& q);
    void updatePoseResults();

    const SceneDocument& doc_;
    EntrySelection& selection_;
    DhStepLink& dhSteps_;
    const WindowParts& parts_;
    bool active_ = false;
};

}  // namespace ll::ui
