#pragma once
// A call waiting in a queue to run on another thread (handover.hpp, work_pool.hpp): any
// callable, move-only ones too, which std::function would refuse.
#include <memory>
#include <type_traits>
#include <utility>

namespace ll::ui {

class PendingCall {
public:
    template <class Call>
    requires(!std::is_same_v<Call, PendingCall>) explicit PendingCall(Call call) : held_(std::make_unique<Held<Call>>(std::move(call))) {}
    void operator()() { held_->run(); }

private:
    struct Base {
        virtual ~Base() = default;
        virtual void run() = 0;
    };
    template <class Call>
    struct Held final : Base {
        explicit Held(Call c) : call(std::move(c)) {}
        void run() override { call(); }
        Call call;
    };
    std::unique_ptr<Base> held_;
};

}  // namespace ll::ui
