#pragma once
// The `lagrangelab` program run as a child, for the benchmarks that time or watch whole
// commands (--render's peak memory, --process).
#include <filesystem>
#include <string>
#include <vector>

namespace ll::bench {

// lagrangelab beside this program's folder: build/app/lagrangelab for build/app/bench/lagrangelab-bench.
std::filesystem::path lagrangelabProgram();

// Runs lagrangelab with `args` (after argv[0]): standard output to /dev/null, standard
// error to `log`, and waits for it. Returns its exit code: 127 when it could not be
// started, 128 + the signal when a signal ended it.
int runLagrangelab(std::vector<std::string> args, const std::filesystem::path& log);

}  // namespace ll::bench
