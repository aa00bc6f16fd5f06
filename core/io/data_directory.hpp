#pragma once
// Where LagrangeLab's run-time data (examples/, …) lives: found from the running
// executable, never from a path compiled in, so an install works wherever its prefix
// is, also after the prefix was moved.
//   installed:  PREFIX/bin/lagrangelab               -> PREFIX/share/lagrangelab
//   build tree: BUILD/app/lagrangelab                -> BUILD/share/lagrangelab (the build
//               links BUILD/share/lagrangelab/examples to the source examples)
//               BUILD/app/bench/lagrangelab-bench    -> BUILD/share/lagrangelab
#include <filesystem>

namespace ll {

// The folder of the running executable (/proc/self/exe, links resolved).
// Throws MessageError (a std::runtime_error) when it cannot be read.
std::filesystem::path executableDirectory();

// executableDirectory()/../share/lagrangelab (../../share/lagrangelab for the benchmarks
// in BUILD/app/bench); normalised.
std::filesystem::path dataDirectory();

// dataDirectory()/examples: the example scenes.
std::filesystem::path examplesDirectory();

}  // namespace ll
