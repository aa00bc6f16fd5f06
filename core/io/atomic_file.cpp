#include "core/io/atomic_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/model/message.hpp"
#include "core/model/message_error.hpp"

namespace ll {
namespace {

// "PATH: cannot save: <what>: <system error>"; what() is in English.
MessageError saveError(const std::string& path, Message what, int error) {
    return MessageError(error ? message(MessageId::CannotSaveForReason, path, std::move(what), std::strerror(error))
                              : message(MessageId::CannotSave, path, std::move(what)));
}

// fsync of a file or directory by name (a descriptor opened for reading may be synced).
bool syncPath(const std::string& path, int flags) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | flags);
    if (fd < 0) return false;
    const bool ok = ::fsync(fd) == 0;
    return ::close(fd) == 0 && ok;
}

void replaceDurably(const std::string& path, const std::function<void(std::ostream&)>& write) {
    const std::string temporary = path + ".tmp-" + std::to_string(::getpid());
    const auto abandon = [&](Message what, int error) {
        ::unlink(temporary.c_str());
        return saveError(path, std::move(what), error);
    };
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) throw saveError(path, message(MessageId::CannotCreateTemporary, temporary), errno);
        try {
            write(out);
        } catch (...) {
            out.close();
            ::unlink(temporary.c_str());
            throw;
        }
        out.flush();
        if (!out) throw abandon(message(MessageId::CannotWriteTemporary, temporary), errno);
        out.close();
        if (out.fail()) throw abandon(message(MessageId::CannotCloseTemporary, temporary), errno);
    }
    // Keep the permissions of the file being replaced.
    struct stat old {};
    if (::stat(path.c_str(), &old) == 0) ::chmod(temporary.c_str(), old.st_mode & 07777);
    if (!syncPath(temporary, 0)) throw abandon(message(MessageId::CannotFlushTemporary, temporary), errno);
    if (::rename(temporary.c_str(), path.c_str()) != 0) throw abandon(message(MessageId::CannotRenameTemporary, temporary), errno);
    // The rename itself lives in the directory; sync it too (best effort).
    std::string directory = std::filesystem::path(path).parent_path().string();
    syncPath(directory.empty() ? "." : directory, O_DIRECTORY);
}

}  // namespace

void saveFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write, Backup backup) {
    std::error_code ec;
    if (backup == Backup::Keep && std::filesystem::exists(path, ec)) {
        const Message cannotKeep = message(MessageId::CannotKeepPrevious, path + ".bak");
        std::ifstream previous(path, std::ios::binary);
        if (!previous) throw saveError(path, cannotKeep, errno);
        replaceDurably(path + ".bak", [&](std::ostream& out) {
            if (previous.peek() != std::ifstream::traits_type::eof()) out << previous.rdbuf();
            if (previous.bad()) throw saveError(path, cannotKeep, errno);
        });
    }
    replaceDurably(path, write);
}

void saveFileAtomically(const std::string& path, const std::string& content, Backup backup) {
    saveFileAtomically(
        path, [&](std::ostream& out) { out.write(content.data(), static_cast<std::streamsize>(content.size())); }, backup);
}

}  // namespace ll
