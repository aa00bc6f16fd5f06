#pragma once
// The one description of each `lagrangelab` command: its synopsis and what it does.
// `lagrangelab help`, `lagrangelab COMMAND --help` and the usage errors of the commands
// all print from here, so they cannot drift apart.
#include <string>

#include "app/usage_message.hpp"

namespace ll::cli {

// The project version from CMake (project(... VERSION ...)), e.g. "0.1.0".
const char* projectVersion();

// "usage: lagrangelab <command> [arguments]" and every command with its synopsis and
// summary, then the exit codes.
std::string overviewUsage();

// "usage: lagrangelab eval SCENE --q ..." and the command's summary (several lines);
// empty for an unknown command.
std::string commandUsage(const std::string& command);

// The synopsis on one line, "usage: lagrangelab eval SCENE ...": what a usage error prints
// ("brug: lagrangelab eval SCENE ..." in Danish; the synopsis itself as the help has it).
UsageMessage usageLine(const std::string& command);
// The synopsis on one line without "usage: lagrangelab ": "eval SCENE --q v1,... ...".
std::string synopsisLine(const std::string& command);

// "eval, simulate, ..., help".
std::string commandNames();

}  // namespace ll::cli
