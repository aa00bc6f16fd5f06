// lagrangelab: Euler–Lagrange modelling of serial robots, from the command line.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <string>

#include "app/cli_options.hpp"
#include "app/command_usage.hpp"
#include "app/commands.hpp"
#include "core/model/diagnostics.hpp"

namespace {

bool isHelp(const std::string& arg) { return arg == "--help" || arg == "-h"; }

}  // namespace

int main(int argc, char** argv) {
    using namespace ll::cli;
    if (argc < 2) {
        std::fputs(overviewUsage().c_str(), stderr);
        return 2;
    }
    const std::string command = argv[1];
    const Args args(argv + 2, argv + argc);
    if (command == "--version" || command == "version") {
        std::printf("lagrangelab %s\n", projectVersion());
        return 0;
    }
    if (isHelp(command) || command == "help") {
        const std::string topic = command == "help" && !args.empty() ? args[0] : "";
        const std::string usage = topic.empty() ? overviewUsage() : commandUsage(topic);
        if (usage.empty()) {
            std::fprintf(stderr, "error: help: unknown command '%s' (commands: %s)\n", topic.c_str(), commandNames().c_str());
            return 2;
        }
        std::fputs(usage.c_str(), stdout);
        return 0;
    }
    // `lagrangelab COMMAND --help`: that command's usage, whatever else is given.
    if (!commandUsage(command).empty() && std::any_of(args.begin(), args.end(), isHelp)) {
        std::fputs(commandUsage(command).c_str(), stdout);
        return 0;
    }
    try {
        if (command == "eval") return evalCommand(args);
        if (command == "simulate") return simulateCommand(args);
        if (command == "integrators") return integratorsCommand(args);
        if (command == "bench") return benchCommand(args);
        if (command == "accuracy") return accuracyCommand(args);
        if (command == "derive") return deriveCommand(args);
        if (command == "render") return renderCommand(args);
        if (command == "codegen") return codegenCommand(args);
        std::fprintf(stderr, "error: unknown command '%s'\n\n%s", command.c_str(), overviewUsage().c_str());
        return 2;
    } catch (const ll::InputError& e) {
        for (const ll::Diagnostic& d : e.diagnostics())
            if (d.severity == ll::Severity::Error) std::cerr << "error: " << d.field << ": " << d.message << '\n';
        return 2;
    } catch (const UsageError& e) {
        std::cerr << "error: " << e.what() << '\n';
        return 2;
    } catch (const std::invalid_argument& e) {
        std::cerr << "error: " << e.what() << '\n';
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << '\n';
        return 1;
    }
}
