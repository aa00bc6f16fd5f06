#pragma once
// One frame per edit: the window's repaint that an edit asks for is held back until the
// edit's result (the re-simulated scene) is on screen, or `limit` milliseconds pass, so
// the typed cell, the robot, the plots and the status line change in the same frame.
//
// Why: when the 3D view was a QOpenGLWidget, every repaint of the window was composed
// through OpenGL (llvmpipe: 15–40 ms at 1280×800 whatever changed) and an edit cost two
// such frames, the cell's and then the result's (~100 ms for the 2R, whose validation
// and simulation take 0.5 and 3 ms). The view now draws in its own native window
// (ui/scene_view), which made a raster frame cheap; the hold still saves the first one
// and keeps a half-updated window (new cell, old robot) from ever being seen.
#include <QObject>
#include <QTimer>

class QWidget;

namespace ll::ui {

class EditFrame : public QObject {
    Q_OBJECT
public:
    // Holds the repaints of the top-level `window` (its QEvent::UpdateRequest).
    explicit EditFrame(QWidget* window, int limitMilliseconds = 100);
    // An edit was made: hold the window's repaints until release() or the limit.
    void hold();
    // The result is shown (or there is none to wait for): paint what is dirty now.
    void release();
    bool holding() const { return holding_; }
    void setLimit(int milliseconds) { limit_.setInterval(milliseconds); }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    QWidget* window_;
    QTimer limit_;
    bool holding_ = false;
    bool swallowed_ = false;  // an update request arrived while holding
};

}  // namespace ll::ui
