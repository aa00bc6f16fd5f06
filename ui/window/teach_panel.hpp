#pragma once
// Teach mode: one slider per joint poses the robot (revolute joints in degrees,
// prismatic in metres, around the initial state) and shows at that pose, live and
// typeset with the unit of every entry, the potential energy E_pot(q), the gravity vector
// g(q) and the mass matrix B(q), evaluated by the numeric core. A click on an entry
// picks it (entryPicked). Robot scenes only (a hand-typed Lagrangian has no joints to
// slide).
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <QWidget>

#include "core/model/scene.hpp"
#include "ui/window/pose_matrices.hpp"

class QLabel;
class QSlider;
class QVBoxLayout;

namespace ll::ui {

class TeachPanel : public QWidget {
    Q_OBJECT
public:
    explicit TeachPanel(QWidget* parent = nullptr);
    ~TeachPanel() override;

    // The robot to pose (copied); keeps the slider values when the joint count is the same.
    void setScene(const Scene& scene);
    // Sets the sliders (and emits poseChanged).
    void setPose(const Eigen::VectorXd& q);
    const Eigen::VectorXd& pose() const { return q_; }
    // E_pot, g and B at the pose, as text prints them ("E_pot(q) = 5.886 J", …).
    QString readout() const;
    PoseMatrices& matrices() { return *matrices_; }

signals:
    void poseChanged(const Eigen::VectorXd& q);
    void entryPicked(ll::present::Quantity quantity, int row, int col);

private:
    void slidersMoved();
    void evaluate();
    struct Model;
    std::unique_ptr<Model> model_;
    QVBoxLayout* sliderBox_;
    std::vector<QSlider*> sliders_;
    std::vector<QLabel*> labels_;
    PoseMatrices* matrices_;
    QLabel* message_;
    Eigen::VectorXd q_;
};

}  // namespace ll::ui
