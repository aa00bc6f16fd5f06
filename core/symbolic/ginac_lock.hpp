#pragma once
// GiNaC is not thread-safe: its reference counts are plain integers and every
// expression shares global constants (0, 1, −1, …), so two threads that work on
// different expressions still race. Every use of GiNaC in LagrangeLab — parsing a
// scene's expressions, deriving, printing, compiling — holds this one process-wide
// lock for the whole operation. What leaves the locked region is plain data
// (strings, display trees, compiled tapes that touch no GiNaC).
//
//   auto lock = ll::symbolic::lockGinac();   // blocks until no other thread uses GiNaC
//
// The mutex is recursive, so a locked function may call another that locks.
#include <mutex>

namespace ll::symbolic {

inline std::recursive_mutex& ginacMutex() {
    static std::recursive_mutex mutex;
    return mutex;
}

[[nodiscard]] inline std::unique_lock<std::recursive_mutex> lockGinac() { return std::unique_lock<std::recursive_mutex>(ginacMutex()); }

}  // namespace ll::symbolic
