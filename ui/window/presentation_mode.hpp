#pragma once
// Presentation mode for a projector: the 3D view on the left (at least half the screen),
// the current derivation step above the energy plot on the right, every text large, no
// menus, tool bars or status line; keys only (space play/pause, ←/→ and the clicker's Page
// Down/Page Up step, F fit, +/− speed, Esc or F11 leave). Leaving restores every dock and
// the window's size exactly. A lesson (ui/window/lesson_mode.hpp) takes the stepping keys.
#include <functional>

#include <QByteArray>
#include <QList>
#include <QObject>
#include <QRect>
#include <QSize>

#include "ui/window/window_parts.hpp"

class QAction;

namespace ll::ui {

class PresentationMode : public QObject {
    Q_OBJECT
public:
    explicit PresentationMode(const WindowParts& parts);

    void setOn(bool on);
    bool on() const { return on_; }
    // What presenting fills: the screen (an invalid size, the default) or, for a scripted
    // picture (--present --size), a window of `size`.
    void setSize(QSize size) { size_ = size; }
    // The dock layout to remember when the window closes: the one from before presenting.
    QByteArray layoutToRemember() const;
    // View → Presentation mode (F11, live while presenting too, the menus hidden).
    QAction* toggleAction() const { return toggle_; }
    // What →, Page Down (+1) and ←, Page Up (−1) do; by default (null) the derivation's
    // next and previous step.
    void setStepper(std::function<void(int)> step) { stepper_ = std::move(step); }

signals:
    void changed(bool on);  // presenting began or ended

private:
    void layOut();

    const WindowParts& parts_;
    QAction* toggle_ = nullptr;
    void step(int delta);

    QList<QAction*> keys_;  // space, arrows, pages, +, −, Esc: live only when presenting
    std::function<void(int)> stepper_;
    bool on_ = false;
    QByteArray layoutBefore_;  // restored when leaving, with …
    QRect geometryBefore_;     // … the window's place and size
    QSize size_;               // invalid: presenting fills the screen
};

}  // namespace ll::ui
