#pragma once
// A display document handed from the thread that shapes it (GiNaC, under its lock) to a
// thread that lays it out while it grows: `derive --format pdf` typesets step 1's items
// while the expanded C and the equations are still being shaped. Plain data only (display
// trees); the reader blocks until what it asks for is there or can no longer come.
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <string>

#include "core/symbolic/derivation_document.hpp"

namespace ll::symbolic {

class DisplayStream {
public:
    // ---- the shaping thread, in this order: open, (putStep, putItem…)…, close; or fail
    // at any time. `head` carries the title (and the form, when it says one); its steps
    // are ignored. describeForm may come before open (the form is chosen first).
    void describeForm(const std::string& form, const std::string& reason);
    void open(const DisplayDocument& head);
    void putStep(DisplayStep step);  // its items follow with putItem
    void putItem(DisplayItem item);  // to the last step put
    void close(const std::string& actuation);
    void fail();
    // A finished document at once (a form that is not shaped item by item).
    void putDocument(const DisplayDocument& document);

    // ---- the reading thread. Each returns nullptr when the stream failed.
    const DisplayDocument* head();  // systemName, form, formReason (no steps)
    // Step i (its items through item()); nullptr past the last step.
    const DisplayStep* step(std::size_t i);
    // Item j of step i; nullptr past its last item.
    const DisplayItem* item(std::size_t i, std::size_t j);
    // After the last step: the actuation line. Empty when failed.
    std::string actuation();
    bool failed();

private:
    struct Step {
        DisplayStep head;
        std::deque<DisplayItem> items;  // a deque: items already read stay in place
    };
    std::mutex mutex_;
    std::condition_variable changed_;
    DisplayDocument head_;
    std::deque<Step> steps_;
    std::string actuation_;
    bool opened_ = false, closed_ = false, failed_ = false;
};

}  // namespace ll::symbolic
