#pragma once
// The DH step-through linked to the window (step 0 of the notes): while its tab is shown,
// the 3D view draws frame i−1 becoming frame i and the DH dimensions, the DH table marks
// the parameter being carried out, and the panel follows the robot's pose.
#include <Eigen/Core>
#include <QObject>

#include "ui/window/window_parts.hpp"

namespace ll::ui {

class DhStepLink : public QObject {
    Q_OBJECT
public:
    explicit DhStepLink(const WindowParts& parts);
    // Whether the step-through's tab is the one shown.
    bool shown() const;
    // The robot is drawn at `q` (the motion or a teach pose): the panel's matrices follow.
    void poseShown(const Eigen::VectorXd& q);

private:
    const WindowParts& parts_;
};

}  // namespace ll::ui
