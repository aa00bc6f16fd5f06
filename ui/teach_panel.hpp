#pragma once
// Teach mode: one slider per joint poses the robot (revolute joints in degrees,
// prismatic in metres, around the initial state) and shows at that pose, live, the
// potential energy E_pot(q) [J], the gravity vector g(q) [N·m or N] and the mass matrix
// B(q), evaluated by the numeric core. Robot scenes only (a hand-typed Lagrangian has
// no joints to slide).
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <QWidget>

#include "core/model/scene.hpp"

class QLabel;
class QSlider;
class QVBoxLayout;
class QPlainTextEdit;

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
    // E_pot, g and B at the pose, as shown.
    QString readout() const;

signals:
    void poseChanged(const Eigen::VectorXd& q);

private:
    void slidersMoved();
    void evaluate();
    struct Model;
    std::unique_ptr<Model> model_;
    QVBoxLayout* sliderBox_;
    std::vector<QSlider*> sliders_;
    std::vector<QLabel*> labels_;
    QPlainTextEdit* readout_;
    Eigen::VectorXd q_;
};

}  // namespace ll::ui
