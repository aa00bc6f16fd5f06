#include "ui/window/control_tuning.hpp"

#include <cmath>

#include <QSignalBlocker>
#include <QSlider>
#include <QTabWidget>

#include "core/math/vector_list.hpp"
#include "ui/document/scene_document.hpp"
#include "ui/window/playback_bar.hpp"
#include "ui/window/tracking_pane.hpp"

namespace ll::ui {
namespace {

std::vector<double> times(const std::vector<double>& v, double factor) {
    std::vector<double> out;
    for (double x : v) out.push_back(x * factor);
    return out;
}

// `now` is `base` times `factor` (to rounding).
bool scaledBy(const std::vector<double>& base, const Eigen::VectorXd& now, double factor) {
    if (static_cast<Eigen::Index>(base.size()) != now.size()) return false;
    for (std::size_t i = 0; i < base.size(); ++i)
        if (std::abs(base[i] * factor - now[static_cast<Eigen::Index>(i)]) > 1e-9 * std::max(1.0, std::abs(now[static_cast<Eigen::Index>(i)])))
            return false;
    return true;
}

}  // namespace

ControlTuning::ControlTuning(SceneDocument& document, const WindowParts& parts) : doc_(document), parts_(parts) {
    TrackingPane& pane = *parts.tracking;
    // An edit for every position a slider is dragged through, all of one drag one undo entry.
    for (QSlider* slider : {&pane.gainSlider(), &pane.payloadSlider()}) {
        slider->setTracking(true);
        connect(slider, &QSlider::sliderPressed, this, [this] { ++drag_; });
    }
    connect(&pane.gainSlider(), &QSlider::valueChanged, this, &ControlTuning::gainsChosen);
    connect(&pane.payloadSlider(), &QSlider::valueChanged, this, &ControlTuning::payloadChosen);
    connect(&doc_, &SceneDocument::validSceneChanged, this, &ControlTuning::sceneChanged);
    connect(&pane, &TrackingPane::timePicked, parts.playback, [playback = parts.playback](double t) {
        playback->pause();
        playback->setTime(t);
    });
    sceneChanged();
}

void ControlTuning::sceneChanged() {
    const Scene& scene = doc_.validScene();
    const bool controlled = !scene.lagrangian && scene.effects.control;
    parts_.plotTabs->setTabVisible(parts_.plotTabs->indexOf(parts_.tracking), controlled);  // a controlled robot's tab
    if (!controlled) {
        kp_.clear(), kd_.clear(), wn_.clear();
        factor_ = 1.0;
        return;
    }
    const Control& c = *scene.effects.control;
    const bool same = c.wn.size() > 0 ? scaledBy(wn_, c.wn, factor_) : scaledBy(kp_, c.kp, factor_) && scaledBy(kd_, c.kd, factor_);
    if (!same) {  // gains of another scene, or edited elsewhere: tuning starts from them
        kp_ = listOf(c.kp), kd_ = listOf(c.kd), wn_ = listOf(c.wn);
        factor_ = 1.0;
    }
    TrackingPane& pane = *parts_.tracking;
    const QSignalBlocker gains(pane.gainSlider()), payload(pane.payloadSlider());
    // Not under the user's hand: the check of an earlier position arrives while dragging on.
    if (!pane.gainSlider().isSliderDown()) pane.gainSlider().setValue(static_cast<int>(std::lround(4 * std::log2(factor_))));
    if (!pane.payloadSlider().isSliderDown()) pane.payloadSlider().setValue(static_cast<int>(std::lround(10 * c.model.payloadMass)));
    pane.showTuning(factor_, c.model.payloadMass);
}

void ControlTuning::gainsChosen(int position) {
    if (kp_.empty() && wn_.empty()) return;
    factor_ = std::pow(2.0, position / 4.0);
    SceneJson control = doc_.value("/effects/control");
    if (!wn_.empty()) control["wn"] = times(wn_, factor_);
    else control["kp"] = times(kp_, factor_), control["kd"] = times(kd_, factor_);
    doc_.setValue("/effects/control", control, tr("Controller gains × %1").arg(factor_, 0, 'g', 3), gesture(parts_.tracking->gainSlider()));
}

void ControlTuning::payloadChosen(int position) {
    if (kp_.empty() && wn_.empty()) return;
    const double kg = position / 10.0;
    SceneJson control = doc_.value("/effects/control");
    if (kg > 0) control["model"]["payload"]["mass"] = kg;
    else if (control.contains("model") && control["model"].contains("payload")) {
        control["model"].erase("payload");
        if (control["model"].empty()) control.erase("model");
    }
    doc_.setValue("/effects/control", control, tr("Payload the controller believes in: %1 kg").arg(kg, 0, 'f', 1),
                  gesture(parts_.tracking->payloadSlider()));
}

int ControlTuning::gesture(const QSlider& slider) const { return slider.isSliderDown() ? drag_ : 0; }

}  // namespace ll::ui
