#include "app/bench/program_run.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include "core/io/data_directory.hpp"

extern char** environ;

namespace ll::bench {

std::filesystem::path lagrangelabProgram() { return (executableDirectory() / ".." / "lagrangelab").lexically_normal(); }

int runLagrangelab(std::vector<std::string> args, const std::filesystem::path& log) {
    const std::string program = lagrangelabProgram().string();
    args.insert(args.begin(), program);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    pid_t pid = 0;
    const int error = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (error != 0) return 127;
    int status = 0;
    if (waitpid(pid, &status, 0) != pid) return 127;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace ll::bench
