#pragma once
// The folder a command writes its files into (`report --out DIR`, `exercise --out DIR`):
// made when missing and tried for writing before the work starts, so a folder that cannot
// be made or written is a usage error now (exit 2), not a failure after minutes of work.
#include <string>

namespace ll::cli {

// Throws UsageError(CannotMakeFolder | FolderNotWritable) naming `out`.
void prepareOutputFolder(const std::string& out);

}  // namespace ll::cli
