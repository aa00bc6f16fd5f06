#pragma once
// Playback of a recorded trajectory: play/pause, restart, a time slider to scrub, speed
// 0.1×–10×, loop. Time advances by wall-clock time × speed between timer ticks, so the
// animation runs at the true speed whatever the frame rate; every change of the
// playback time is reported once (timeChanged), and the views sample the trajectory at
// that time.
#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QSlider;
class QToolButton;

namespace ll::ui {

class PlaybackBar : public QWidget {
    Q_OBJECT
public:
    explicit PlaybackBar(QWidget* parent = nullptr);

    void setRange(double start, double end);  // [s]
    double time() const { return t_; }
    double startTime() const { return start_; }
    double endTime() const { return end_; }
    double speed() const;
    bool isPlaying() const { return timer_.isActive(); }
    bool loops() const;

public slots:
    void play();
    void pause();
    void togglePlay();
    void restart();
    void setTime(double t);
    void setSpeed(double factor);
    void setLoop(bool on);
    void faster();  // speed steps 0.1, 0.25, 0.5, 1, 2, 5, 10
    void slower();

signals:
    void timeChanged(double t);
    void playingChanged(bool playing);

private:
    void tick();
    void showTime();
    QToolButton *play_, *restart_;
    QSlider* slider_;
    QLabel* label_;
    QDoubleSpinBox* speed_;
    QCheckBox* loop_;
    QTimer timer_;
    QElapsedTimer clock_;
    double start_ = 0, end_ = 0, t_ = 0;
};

}  // namespace ll::ui
