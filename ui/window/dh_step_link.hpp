#pragma once
// The DH step-through linked to the window (step 0 of the notes). "Row by row": while
// shown, the 3D view draws frame i−1 becoming frame i and the DH dimensions, the DH table
// marks the parameter being carried out, and the panel follows the robot's pose. "Find
// the DH parameters": while shown, the robot stands at home (playback paused) with the
// construction's marks over it instead of its own frames.
#include <Eigen/Core>
#include <QObject>

#include "core/model/scene.hpp"
#include "ui/window/window_parts.hpp"

namespace ll::ui {

class DhStepLink : public QObject {
    Q_OBJECT
public:
    explicit DhStepLink(const WindowParts& parts);
    // Whether the step-through's "Row by row" page is the one shown.
    bool shown() const;
    // Whether "Find the DH parameters" is shown with a robot: the robot is held at home.
    bool holdsHome() const;
    // Poses the robot at home (q = 0), as it stands while its frames are being found.
    void showHome();
    // A new valid scene: both pages take its robot (and a URDF's link frames).
    void sceneChanged(const Scene& scene);
    // The robot is drawn at `q` (the motion or a teach pose): the panel's matrices follow.
    void poseShown(const Eigen::VectorXd& q);

signals:
    // The robot is no longer held at home: the window shows the playback's pose again.
    void homeReleased();

private:
    void pageChanged();
    const WindowParts& parts_;
    bool holding_ = false;
    int dof_ = 0;
};

}  // namespace ll::ui
