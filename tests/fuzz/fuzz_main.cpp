// libFuzzer's entry point for one target: LL_FUZZ_TARGET is the body's name
// (tests/fuzz/CMakeLists.txt compiles this file once per target).
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) { return ll::fuzz::LL_FUZZ_TARGET(data, size); }
