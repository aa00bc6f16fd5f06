#include "ui/window/playback_bar.hpp"

#include "ui/window/relabel.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QVBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>
#include <QToolButton>

namespace ll::ui {

namespace {
constexpr int kSliderSteps = 10000;
constexpr std::array<double, 7> kSpeeds = {0.1, 0.25, 0.5, 1, 2, 5, 10};
}  // namespace

PlaybackBar::PlaybackBar(QWidget* parent) : QWidget(parent) {
    auto* rows = new QVBoxLayout(this);
    rows->setContentsMargins(4, 2, 4, 2);
    rows->setSpacing(0);
    auto* layout = new QHBoxLayout;
    play_ = new QToolButton(this);
    play_->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
    restart_ = new QToolButton(this);
    restart_->setIcon(style()->standardIcon(QStyle::SP_MediaSkipBackward));
    slider_ = new QSlider(Qt::Horizontal, this);
    slider_->setRange(0, kSliderSteps);
    label_ = new QLabel(this);
    label_->setMinimumWidth(150);
    label_->setContentsMargins(6, 0, 0, 0);
    speed_ = new QDoubleSpinBox(this);
    speed_->setRange(0.1, 10.0);
    speed_->setSingleStep(0.1);
    speed_->setDecimals(2);
    speed_->setValue(1.0);
    loop_ = new QCheckBox(this);
    auto* speedLabel = new QLabel(this);
    (*new Relabel(this))([this, speedLabel] {
        play_->setToolTip(tr("Play / pause (Space)"));
        restart_->setToolTip(tr("Restart"));
        slider_->setToolTip(tr("Playback time: drag to scrub"));
        speed_->setSuffix(tr("×"));
        speed_->setToolTip(tr("Playback speed (simulated seconds per second)"));
        loop_->setText(tr("loop"));
        speedLabel->setText(tr("speed"));
        showTime();
    });
    loop_->setChecked(true);
    // The time slider on a row of its own, as wide as the view: beside the buttons and
    // labels it was squeezed to a box in Danish at 1280×800.
    rows->addWidget(slider_);
    rows->addLayout(layout);
    layout->addWidget(play_);
    layout->addWidget(restart_);
    layout->addWidget(label_);
    layout->addStretch(1);
    layout->addWidget(speedLabel);
    layout->addWidget(speed_);
    layout->addWidget(loop_);
    timer_.setInterval(15);
    timer_.setTimerType(Qt::PreciseTimer);
    connect(&timer_, &QTimer::timeout, this, &PlaybackBar::tick);
    connect(play_, &QToolButton::clicked, this, &PlaybackBar::togglePlay);
    connect(restart_, &QToolButton::clicked, this, &PlaybackBar::restart);
    connect(slider_, &QSlider::valueChanged, this, [this](int v) { setTime(start_ + (end_ - start_) * v / kSliderSteps); });
    showTime();
}

void PlaybackBar::setRange(double start, double end) {
    start_ = start;
    end_ = std::max(end, start);
    t_ = std::clamp(t_, start_, end_);
    showTime();
}

double PlaybackBar::speed() const { return speed_->value(); }
bool PlaybackBar::loops() const { return loop_->isChecked(); }

void PlaybackBar::play() {
    if (isPlaying()) return;
    if (t_ >= end_) t_ = start_;
    clock_.start();
    timer_.start();
    play_->setIcon(style()->standardIcon(QStyle::SP_MediaPause));
    emit playingChanged(true);
}

void PlaybackBar::pause() {
    if (!isPlaying()) return;
    timer_.stop();
    play_->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
    emit playingChanged(false);
}

void PlaybackBar::togglePlay() { isPlaying() ? pause() : play(); }

void PlaybackBar::restart() { setTime(start_); }

void PlaybackBar::setTime(double t) {
    t_ = std::clamp(t, start_, end_);
    showTime();
    emit timeChanged(t_);
}

void PlaybackBar::setSpeed(double factor) { speed_->setValue(std::clamp(factor, 0.1, 10.0)); }
void PlaybackBar::setLoop(bool on) { loop_->setChecked(on); }

void PlaybackBar::faster() {
    for (double s : kSpeeds)
        if (s > speed() + 1e-9) return setSpeed(s);
}

void PlaybackBar::slower() {
    for (auto it = kSpeeds.rbegin(); it != kSpeeds.rend(); ++it)
        if (*it < speed() - 1e-9) return setSpeed(*it);
}

void PlaybackBar::tick() {
    const double elapsed = clock_.nsecsElapsed() * 1e-9;
    clock_.restart();
    double t = t_ + elapsed * speed();
    if (t >= end_) {
        if (loops() && end_ > start_) {
            t = start_ + std::fmod(t - start_, end_ - start_);
        } else {
            t = end_;
            pause();
        }
    }
    setTime(t);
}

void PlaybackBar::showTime() {
    label_->setText(tr("t = %1 s / %2 s").arg(t_, 0, 'f', 3).arg(end_, 0, 'f', 2));
    const QSignalBlocker block(slider_);
    slider_->setValue(end_ > start_ ? static_cast<int>(std::lround((t_ - start_) / (end_ - start_) * kSliderSteps)) : 0);
}

}  // namespace ll::ui
