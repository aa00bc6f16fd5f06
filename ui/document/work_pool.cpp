#include "ui/document/work_pool.hpp"

#include <optional>

namespace ll::ui {

WorkPool::~WorkPool() {
    pool_.waitForDone();           // before the queue and its mutex go: a job may be taking its turn
    std::lock_guard lock(mutex_);  // after the last job's hand-over, as TSan sees it
    jobs_.clear();
}

void WorkPool::runOne() {
    std::optional<PendingCall> job;
    {
        std::lock_guard lock(mutex_);
        if (jobs_.empty()) return;
        job.emplace(std::move(jobs_.front()));
        jobs_.pop_front();
    }
    (*job)();  // the job and its copies are destroyed on this thread, after it ran
}

}  // namespace ll::ui
