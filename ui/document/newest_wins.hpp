#pragma once
// "The newest request wins", written once for every worker of the window (the live
// simulation and derivation, the document's check, the work–precision sweep, the typeset
// view's own derivation). Each request gets a number, newer than every one before; the
// work for it gets a fresh cancel flag, and beginning new work sets the flag of the work
// before it (its result would be dropped anyway). A result travels back to the owner's
// thread through a Handover (ui/document/handover.hpp), and runs there only if no newer
// request was made meanwhile. The worker shares nothing else with the owner: copies in,
// plain results back.
//
// Lifetime: a NewestWins is a member of the QObject that owns the work, made on its
// thread; its Handover goes with it, so calls still queued are dropped when the owner is
// gone, and the owner waits for its workers before it dies (their flag set by ~NewestWins
// or the owner's cancel()).
#include <atomic>
#include <memory>
#include <utility>

#include "ui/document/handover.hpp"

namespace ll::ui {

class NewestWins {
public:
    using Flag = std::shared_ptr<std::atomic<bool>>;

    NewestWins() = default;
    NewestWins(const NewestWins&) = delete;
    NewestWins& operator=(const NewestWins&) = delete;
    ~NewestWins() { cancel(); }

    // A new request: its number. Results of every older request are stale from now on.
    int request() { return ++newest_; }
    int newest() const { return newest_; }
    bool isNewest(int number) const { return number >= newest_; }

    // Work for the newest request begins: the work before it is told to stop (its flag set)
    // and this work's own flag is returned.
    Flag begin() {
        cancel();
        running_ = std::make_shared<std::atomic<bool>>(false);
        return running_;
    }
    // Tells the running work to stop; the request stays the newest.
    void cancel() {
        if (running_) running_->store(true);
    }

    // From a worker: `show` runs on the owner's thread, and only if `number` is still the
    // newest request then.
    template <class Show>
    void deliver(int number, Show show) {
        back_.post([this, number, show = std::move(show)]() mutable {
            if (isNewest(number)) show();
        });
    }

private:
    int newest_ = 0;
    Flag running_;
    Handover back_;
};

}  // namespace ll::ui
