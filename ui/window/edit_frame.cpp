#include "ui/window/edit_frame.hpp"

#include <QCoreApplication>
#include <QEvent>
#include <QWidget>

namespace ll::ui {

EditFrame::EditFrame(QWidget* window, int limitMilliseconds) : QObject(window), window_(window) {
    limit_.setSingleShot(true);
    limit_.setInterval(limitMilliseconds);
    connect(&limit_, &QTimer::timeout, this, &EditFrame::release);
    window_->installEventFilter(this);
}

void EditFrame::hold() {
    holding_ = true;
    limit_.start();
}

void EditFrame::release() {
    limit_.stop();
    if (!holding_) return;
    holding_ = false;
    // Qt sends a window one request until it has painted, so the swallowed one is posted
    // again, ahead of queued calls (Qt posts its own at low priority, behind them): a
    // derivation arriving after the result would otherwise be laid out before the frame.
    if (swallowed_) QCoreApplication::postEvent(window_, new QEvent(QEvent::UpdateRequest), Qt::HighEventPriority);
    swallowed_ = false;
}

bool EditFrame::eventFilter(QObject* watched, QEvent* event) {
    if (holding_ && watched == window_ && event->type() == QEvent::UpdateRequest) {
        swallowed_ = true;
        return true;
    }
    return QObject::eventFilter(watched, event);
}

}  // namespace ll::ui
