#include "ui/document/handover.hpp"

namespace ll::ui {

Handover::~Handover() {
    std::lock_guard lock(mutex_);  // results never drained are dropped here, after their workers' last post
    calls_.clear();
}

void Handover::drain() {
    std::vector<std::unique_ptr<Pending>> calls;
    {
        std::lock_guard lock(mutex_);
        calls.swap(calls_);
    }
    for (const auto& call : calls) call->run();  // a call may post again: that one waits for the next drain
}

}  // namespace ll::ui
