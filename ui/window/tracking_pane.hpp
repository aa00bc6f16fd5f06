#pragma once
// The "Tracking" tab of a scene with a controller (effects.control): what the controller
// did along the run, one joint at a time, with the playback cursor — the tracking error
// e_i and its rate ė_i; the controller's torque split into its terms (B̂ q̈_d, Ĉ q̇, ĝ,
// K_p e, K_d ė) beside the torque applied; for PD laws holding a pose the Lyapunov
// function V(t), and its rate V̇ over −q̇ᵀK_d q̇ with the sentence that says why they are
// equal (q̇ᵀ(Ḃ − 2C)q̇ = 0) or what makes them differ (a wrong ĝ, friction, the limits).
#include <memory>

#include <QWidget>

#include "core/model/scene.hpp"
#include "core/simulation/control_history.hpp"

class QComboBox;
class QLabel;
class QSlider;

namespace ll::ui {

class TrajectoryChart;

class TrackingPane : public QWidget {
    Q_OBJECT
public:
    enum class Show { Error, Torque, Lyapunov, LyapunovRate };
    explicit TrackingPane(QWidget* parent = nullptr);

    // What the controller of a run of `scene` did; null: none yet (or no controller).
    void setControl(std::shared_ptr<const ControlHistory> history, std::shared_ptr<const Scene> scene, std::vector<double> t);
    void setJoint(int joint);  // 0-based
    void setShow(Show show);
    Show show() const;
    void setCursorTime(double t);
    TrajectoryChart& chart() { return *chart_; }
    QString note() const;  // the sentence under the plot
    // The tuning sliders (ui/window/control_tuning drives them): the gains' factor, 2^(k/4)
    // for position k in −8..8, and the believed payload in 0.1 kg steps, 0..50.
    QSlider& gainSlider() { return *gain_; }
    QSlider& payloadSlider() { return *payload_; }
    void showTuning(double factor, double payload);  // the sliders' texts

signals:
    void timePicked(double t);

private:
    void redraw();
    void fillShows();

    std::shared_ptr<const ControlHistory> history_;
    std::shared_ptr<const Scene> scene_;
    std::vector<double> t_;
    QComboBox* joint_;
    QComboBox* show_;
    QLabel* law_;
    QLabel* note_;
    TrajectoryChart* chart_;
    QSlider *gain_, *payload_;
    QLabel *gainText_, *payloadText_;
};

}  // namespace ll::ui
