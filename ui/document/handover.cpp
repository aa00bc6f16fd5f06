#include "ui/document/handover.hpp"

namespace ll::ui {

Handover::~Handover() {
    std::lock_guard lock(mutex_);  // results never drained are dropped here, after their workers' last post
    calls_.clear();
}

void Handover::drain() {
    std::vector<PendingCall> calls;
    {
        std::lock_guard lock(mutex_);
        calls.swap(calls_);
    }
    for (PendingCall& call : calls) call();  // a call may post again: that one waits for the next drain
}

}  // namespace ll::ui
