#pragma once
// A worker's result handed to the thread that owns it: the one way a result crosses back
// in the window. post() may be called from any thread; the call runs later on the thread
// this object lives on (the owner's), in the order posted.
//
// Why not QMetaObject::invokeMethod with a lambda: the lambda is copied into a slot
// object the worker allocates, and Qt's event queue hands that object over under its own
// futex-based mutex, which ThreadSanitizer does not see (Debian's Qt is not built with
// it), so every result read on the owner's thread is reported as a race with the worker
// that wrote it (found on 2026-11-29, issue 47, test_answer_checking). Here the call is
// stored under a std::mutex, which TSan models, and the wake-up carries nothing of ours
// (a queued call of drain() by name, made and freed by Qt itself): the sanitizer sees the
// same happens-before the program relies on.
//
// Lifetime: a member of the object that owns the work, made on its thread; Qt drops
// wake-ups still queued when it is destroyed, and the owner waits for its workers before
// it dies, so no worker posts to a destroyed Handover.
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include <QObject>

#include "ui/document/pending_call.hpp"

namespace ll::ui {

class Handover : public QObject {
    Q_OBJECT
public:
    Handover() = default;
    ~Handover() override;

    template <class Call>
    void post(Call call) {
        {
            std::lock_guard lock(mutex_);
            calls_.emplace_back(std::move(call));
        }
        QMetaObject::invokeMethod(this, "drain", Qt::QueuedConnection);
    }

private:
    Q_INVOKABLE void drain();

    std::mutex mutex_;
    std::vector<PendingCall> calls_;
};

}  // namespace ll::ui
