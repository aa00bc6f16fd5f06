#pragma once
// This program run again as a child, for the benchmarks that time or watch whole
// commands (bench --render's peak memory, bench --process).
#include <filesystem>
#include <string>
#include <vector>

namespace ll::cli {

// Runs /proc/self/exe with `args` (after argv[0]): standard output to /dev/null, standard
// error to `log`, and waits for it. Returns its exit code: 127 when it could not be
// started, 128 + the signal when a signal ended it.
int runSelf(std::vector<std::string> args, const std::filesystem::path& log);

}  // namespace ll::cli
