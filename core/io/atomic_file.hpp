#pragma once
// Replacing a file so that it is, at every moment and after a crash, either the old
// file or the new one, whole: the content goes to PATH.tmp-<pid> in the same
// directory, is flushed to the disk (fsync), renamed over PATH (atomic within a
// directory), and the directory is synced. The file keeps the permissions of the one
// it replaces. With Backup::Keep an existing PATH is first copied the same way to
// PATH.bak, the recovery copy. Every writer of a file uses this one routine: scenes
// (with the .bak), trajectories, tables and plots.
#include <functional>
#include <ostream>
#include <string>

namespace ll {

enum class Backup {
    None,  // outputs a command can write again (trajectories, tables, plots)
    Keep,  // the user's own work (scene files): PATH.bak holds the previous content
};

// write(out) produces the content, streamed (a trajectory may be large). Throws
// MessageError (a std::runtime_error, core/model/message_error.hpp) "PATH: cannot save:
// <what>: <system error>"; PATH is then untouched and no temporary file is left.
void saveFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write, Backup backup);
void saveFileAtomically(const std::string& path, const std::string& content, Backup backup);

}  // namespace ll
