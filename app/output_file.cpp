#include "app/output_file.hpp"

#include <filesystem>

#include <unistd.h>

#include "app/usage_error.hpp"

namespace ll::cli {

void requireWritableOutputFile(const std::string& out) {
    std::error_code error;
    const std::filesystem::path dir = std::filesystem::absolute(out, error).parent_path();
    const bool isDir = !error && std::filesystem::is_directory(dir, error);
    if (!isDir || ::access(dir.c_str(), W_OK) != 0)
        throw UsageError(isDir ? UsageId::OutFolderNotWritable : UsageId::OutFolderMissing, out);
}

}  // namespace ll::cli
