#include "core/io/data_directory.hpp"

#include <stdexcept>
#include <system_error>

#include "core/model/message.hpp"
#include "core/model/message_error.hpp"

namespace ll {

namespace fs = std::filesystem;

fs::path executableDirectory() {
    std::error_code error;
    const fs::path exe = fs::read_symlink("/proc/self/exe", error);
    if (error) throw MessageError(message(MessageId::ProgramLocationUnknown, error.message()));
    return exe.parent_path();
}

fs::path dataDirectory() {
    const fs::path exe = executableDirectory();
    const bool benchmarks = exe.filename() == "bench" && exe.parent_path().filename() == "app";
    return (exe / (benchmarks ? "../.." : "..") / "share" / "lagrangelab").lexically_normal();
}

fs::path examplesDirectory() { return dataDirectory() / "examples"; }

}  // namespace ll
