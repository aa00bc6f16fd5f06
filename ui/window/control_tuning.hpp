#pragma once
// Tuning the controller live, from the Tracking tab: a slider scales the gains (K_p, K_d,
// or the natural frequency wn) from those the scene had when tuning began, another sets
// the payload the controller's model believes in (effects.control.model.payload.mass,
// 0–5 kg: a wrong ĝ in one move). The run follows while a slider is dragged (the live
// simulation: newest edit wins, so only the positions it has time for are run), and a
// drag, from press to release, is one undoable edit of effects.control. Also shows the
// Tracking tab only for a robot with a controller, and moves the playback where its plot
// is clicked.
#include <QObject>

class QSlider;

#include "ui/window/window_parts.hpp"

namespace ll::ui {

class SceneDocument;

class ControlTuning : public QObject {
    Q_OBJECT
public:
    ControlTuning(SceneDocument& document, const WindowParts& parts);

private:
    void sceneChanged();  // the sliders follow the scene (an edit, undo, another file)
    void gainsChosen(int position);
    void payloadChosen(int position);
    int gesture(const QSlider& slider) const;  // the drag's, or 0 (a click, a key)

    SceneDocument& doc_;
    const WindowParts& parts_;
    // The gains the factor multiplies: the scene's when tuning began, or after another
    // edit changed them.
    std::vector<double> kp_, kd_, wn_;
    double factor_ = 1.0;
    int drag_ = 0;  // the latest drag's number (SceneDocument::setValue's gesture)
};

}  // namespace ll::ui
