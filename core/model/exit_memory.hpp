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

namespace ll {

void leaveMemoryToExit();
bool memoryLeftToExit();

// Frees `object` now, or keeps it until the process exits (see above). Thread-safe.
void dispose(std::shared_ptr<const void> object);

}  // namespace ll
