#include "app/graphics_handoff.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <system_error>

#include <unistd.h>

#include "app/commands.hpp"
#include "core/io/data_directory.hpp"

namespace ll::cli {
namespace {

char** rememberedArgv = nullptr;
// Set in the environment of the exec, so that lagrangelab-gui's children (bench --gui
// starts lagrangelab) are unaffected once it clears it.
constexpr const char* kHandedOver = "LAGRANGELAB_HANDED_OVER";

// The value `--name` gets, read the way Options reads it (`--name value`, `--name=value`,
// the last one wins); nullopt when absent.
std::optional<std::string> optionValue(const Args& args, const std::string& name) {
    std::optional<std::string> value;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--" + name) {
            if (i + 1 < args.size()) value = args[++i];
        } else if (args[i].rfind("--" + name + "=", 0) == 0) {
            value = args[i].substr(name.size() + 3);
        }
    }
    return value;
}

bool hasFlag(const Args& args, const std::string& name) {
    for (const std::string& a : args)
        if (a == "--" + name || a.rfind("--" + name + "=", 0) == 0) return true;
    return false;
}

}  // namespace

// lagrangelab's own painting functions hand the command line over too, only later
// (app/text_only_program.cpp): a command this misses would still paint, but after its
// work, which then runs again (and prints again) in lagrangelab-gui. It reads options
// as Options does (`--name value`, `--name=value`, the last wins); the command lines of
// tests/test_graphics_handoff check it.
bool commandPaints(const std::string& command, const Args& args) {
    if (command == "render") return true;
    if (command == "derive") {
        const std::optional<std::string> format = optionValue(args, "format");
        return format && (*format == "pdf" || *format == "svg" || *format == "png");
    }
    if (command == "accuracy") {  // an empty --out draws no plot
        const std::optional<std::string> out = optionValue(args, "out");
        return out && !out->empty();
    }
    if (command == "bench") return hasFlag(args, "gui") || hasFlag(args, "render") || hasFlag(args, "typeset");
    return false;
}

void rememberCommandLine(char** argv) { rememberedArgv = argv; }

std::filesystem::path graphicsProgram() {
    if (const char* chosen = std::getenv("LAGRANGELAB_GUI"); chosen != nullptr && *chosen != '\0') return chosen;
    const std::filesystem::path dir = executableDirectory();
    std::error_code error;
    if (std::filesystem::exists(dir / "lagrangelab-gui", error)) return dir / "lagrangelab-gui";
    return (dir / ".." / "libexec" / "lagrangelab" / "lagrangelab-gui").lexically_normal();
}

std::filesystem::path textProgram() {
    const std::filesystem::path dir = executableDirectory();
    std::error_code error;
    if (std::filesystem::exists(dir / "lagrangelab", error)) return dir / "lagrangelab";
    return (dir / ".." / ".." / "bin" / "lagrangelab").lexically_normal();
}

int handOverToGraphicsProgram() {
    std::string program;
    try {
        program = graphicsProgram().string();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
    // Handed over once only: a LAGRANGELAB_GUI that names lagrangelab (or a script
    // starting it) would otherwise exec forever. lagrangelab-gui clears the mark.
    if (std::getenv(kHandedOver) != nullptr) {
        std::fprintf(stderr, "error: %s handed the command back instead of running it: LAGRANGELAB_GUI must name lagrangelab-gui\n",
                     program.c_str());
        return 1;
    }
    ::setenv(kHandedOver, "1", 1);
    std::fflush(stdout);
    std::fflush(stderr);
    ::execv(program.c_str(), rememberedArgv);
    const int error = errno;
    ::unsetenv(kHandedOver);
    std::fprintf(stderr,
                 "error: cannot start %s, which draws the window, videos, plots and typeset pages: %s (reinstall lagrangelab, "
                 "or set LAGRANGELAB_GUI to lagrangelab-gui)\n",
                 program.c_str(), std::strerror(error));
    return 1;
}

void clearHandoverMark() { ::unsetenv(kHandedOver); }

bool hasDisplay() { return std::getenv("DISPLAY") != nullptr || std::getenv("WAYLAND_DISPLAY") != nullptr; }

}  // namespace ll::cli
