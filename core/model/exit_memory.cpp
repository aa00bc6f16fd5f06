#include "core/model/exit_memory.hpp"

#include <atomic>
#include <mutex>
#include <vector>

namespace ll {
namespace {

std::atomic<bool> leaving{false};

std::mutex keptMutex;
// Never destroyed (no destructor runs at exit), and reachable from here.
std::vector<std::shared_ptr<const void>>* const kept = new std::vector<std::shared_ptr<const void>>;

}  // namespace

void leaveMemoryToExit() { leaving.store(true); }
bool memoryLeftToExit() { return leaving.load(); }

void dispose(std::shared_ptr<const void> object) noexcept {
    if (!object || !leaving.load()) return;  // the last owner: freed here
    try {
        const std::lock_guard lock(keptMutex);
        kept->push_back(std::move(object));
    } catch (...) {
        // No room to keep it (or no lock): freed here instead, which is only slower.
        // dispose runs in destructors (Disposing), also while an exception passes.
    }
}

}  // namespace ll
