#pragma once
// Memory a short-lived command leaves to its exit instead of freeing it piece by piece.
// The expanded Panda's derivation, its display trees and the display builder's caches
// are millions of small blocks; freeing them one by one took about 0.1 s of `derive`'s
// 2.5 s, just before the process ended and the system took all of its memory back at
// once. (Compilers do the same: clang's -disable-free.)
//
// A process that runs one command and exits calls leaveMemoryToExit() once; code that is
// done with a large structure hands it to dispose(), which frees it at once, or, after
// leaveMemoryToExit(), keeps it, reachable (a leak checker reports nothing) and never
// destroyed. A window never calls leaveMemoryToExit: every derivation there is freed.
// What is kept is never touched again: it may refer to objects already gone (the display
// builder's presenter to the derivation it read), and nothing walks or destroys the list.
#include <memory>
#include <type_traits>
#include <utility>

namespace ll {

void leaveMemoryToExit();
bool memoryLeftToExit();

// Frees `object` now, or keeps it until the process exits (see above). Thread-safe;
// never throws (when it cannot keep the object, it frees it).
void dispose(std::shared_ptr<const void> object) noexcept;

// A T made on the heap, handed to dispose() when this owner goes (also when an exception
// passes), or earlier by disposeNow():
//     Disposing<DisplayBuilder> build(options);  // its caches: freed at the end, or left to the exit
template <class T>
class Disposing {
public:
    template <class... Args>
    explicit Disposing(Args&&... args) : object_(std::make_shared<T>(std::forward<Args>(args)...)) {}
    ~Disposing() { dispose(std::move(object_)); }
    Disposing(const Disposing&) = delete;
    Disposing& operator=(const Disposing&) = delete;
    T& operator*() const { return *object_; }
    T* operator->() const { return object_.get(); }
    // Hands it to dispose() now; it is not used after.
    void disposeNow() { dispose(std::move(object_)); }

private:
    std::shared_ptr<T> object_;
};

// Hands a value to dispose(), moved into an owner on the heap.
template <class T>
void disposeValue(T&& value) {
    dispose(std::make_shared<std::remove_cvref_t<T>>(std::forward<T>(value)));
}

}  // namespace ll
