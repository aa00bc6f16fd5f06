#pragma once
// The threads a window's worker runs its jobs on: a QThreadPool whose jobs are handed over
// under a std::mutex. start() is called on the owner's thread; each job runs once, on a
// thread of the pool (in the order started when the pool has one thread).
//
// Why not QThreadPool::start(lambda) directly: the lambda, with the copies it carries in
// (the scene, the answer, the key), is made on the owner's thread and read on a pool
// thread that Qt hands it to under its own futex-based mutex, which ThreadSanitizer does
// not see (Debian's Qt is not built with it); once a pool thread is reused, every job's
// captures are reported as a race (found on 2026-11-29, issue 47, test_answer_checking).
// Here the job waits in a queue under a std::mutex, which TSan models, and what Qt runs
// carries nothing of ours but this object's address. Results come back through a
// Handover (handover.hpp), the same way round.
//
// Lifetime: a member of the object that owns the work; its destructor waits for the
// running jobs (as QThreadPool's does), so the owner's members they use outlive them only
// if they are declared before it or the owner waits first (every owner here cancels and
// waits in its destructor).
#include <deque>
#include <memory>
#include <mutex>
#include <utility>

#include <QThreadPool>

#include "ui/document/pending_call.hpp"

namespace ll::ui {

class WorkPool {
public:
    WorkPool() = default;
    WorkPool(const WorkPool&) = delete;
    WorkPool& operator=(const WorkPool&) = delete;
    ~WorkPool();

    template <class Job>
    void start(Job job) {
        {
            std::lock_guard lock(mutex_);
            jobs_.emplace_back(std::move(job));
        }
        pool_.start([this] { runOne(); });
    }
    void setMaxThreadCount(int threads) { pool_.setMaxThreadCount(threads); }
    // Blocks until every job started has run.
    void waitForDone() { pool_.waitForDone(); }

private:
    void runOne();

    QThreadPool pool_;
    std::mutex mutex_;
    std::deque<PendingCall> jobs_;
};

}  // namespace ll::ui
