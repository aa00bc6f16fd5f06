#pragma once
// Stopping long work from another thread: the caller owns a std::atomic<bool> and sets
// it; the work checks it between pieces (derivation entries, integration steps) and
// stops. A derivation stops by throwing Cancelled (its partial result is useless); a
// simulation returns its partial trajectory with status Cancelled instead.
#include <atomic>
#include <stdexcept>

namespace ll {

class Cancelled : public std::runtime_error {
public:
    Cancelled() : std::runtime_error("cancelled") {}
};

// Throws Cancelled when `cancel` is set (a null flag never cancels).
inline void throwIfCancelled(const std::atomic<bool>* cancel) {
    if (cancel && cancel->load(std::memory_order_relaxed)) throw Cancelled();
}

}  // namespace ll
