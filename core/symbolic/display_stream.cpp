#include "core/symbolic/display_stream.hpp"

#include <utility>

namespace ll::symbolic {

void DisplayStream::describeForm(const std::string& form, const std::string& reason) {
    const std::lock_guard lock(mutex_);
    head_.form = form;
    head_.formReason = reason;
}

void DisplayStream::open(const DisplayDocument& head) {
    {
        const std::lock_guard lock(mutex_);
        head_.systemName = head.systemName;
        head_.coordinateNames = head.coordinateNames;
        if (!head.form.empty()) {
            head_.form = head.form;
            head_.formReason = head.formReason;
        }
        opened_ = true;
    }
    changed_.notify_all();
}

void DisplayStream::putStep(DisplayStep step) {
    step.items.clear();
    {
        const std::lock_guard lock(mutex_);
        steps_.push_back({std::move(step), {}});
    }
    changed_.notify_all();
}

void DisplayStream::putItem(DisplayItem item) {
    {
        const std::lock_guard lock(mutex_);
        steps_.back().items.push_back(std::move(item));
    }
    changed_.notify_all();
}

void DisplayStream::close(const std::string& actuation) {
    {
        const std::lock_guard lock(mutex_);
        actuation_ = actuation;
        closed_ = true;
    }
    changed_.notify_all();
}

void DisplayStream::fail() {
    {
        const std::lock_guard lock(mutex_);
        failed_ = true;
    }
    changed_.notify_all();
}

void DisplayStream::putDocument(const DisplayDocument& document) {
    open(document);
    for (const DisplayStep& step : document.steps) {
        putStep(step);
        for (const DisplayItem& item : step.items) putItem(item);
    }
    close(document.actuation);
}

const DisplayDocument* DisplayStream::head() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return opened_ || failed_; });
    return failed_ ? nullptr : &head_;
}

const DisplayStep* DisplayStream::step(std::size_t i) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return failed_ || closed_ || steps_.size() > i; });
    if (failed_ || steps_.size() <= i) return nullptr;
    return &steps_[i].head;
}

const DisplayItem* DisplayStream::item(std::size_t i, std::size_t j) {
    std::unique_lock lock(mutex_);
    // Step i has no more items once a later step has begun or the stream is closed.
    changed_.wait(lock, [&] { return failed_ || closed_ || steps_.size() > i + 1 || steps_[i].items.size() > j; });
    if (failed_ || steps_[i].items.size() <= j) return nullptr;
    return &steps_[i].items[j];
}

std::string DisplayStream::actuation() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return failed_ || closed_; });
    return failed_ ? std::string() : actuation_;
}

bool DisplayStream::failed() {
    const std::lock_guard lock(mutex_);
    return failed_;
}

}  // namespace ll::symbolic
