#include "app/output_folder.hpp"

#include <filesystem>
#include <fstream>

#include "app/usage_error.hpp"

namespace ll::cli {

void prepareOutputFolder(const std::string& out) {
    namespace fs = std::filesystem;
    std::error_code error;
    fs::create_directories(out, error);
    if (!fs::is_directory(out)) throw UsageError(UsageId::CannotMakeFolder, out, error.message());
    const fs::path probe = fs::path(out) / ".lagrangelab-write-test";
    std::ofstream test(probe);
    if (!test) throw UsageError(UsageId::FolderNotWritable, out);
    test.close();
    fs::remove(probe, error);
}

}  // namespace ll::cli
