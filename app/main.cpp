// lagrangelab: Euler–Lagrange modelling of serial robots, in a window or from the
// command line. The commands that paint (the window, render, derive --format
// pdf|svg|png, accuracy --out) start Qt; the others never do.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

#include "app/cli_options.hpp"
#include "core/present/diagnostic_text.hpp"
#include "app/command_usage.hpp"
#include "app/commands.hpp"
#include "app/offscreen_gui.hpp"
#include "core/model/diagnostics.hpp"
#include "core/model/message_error.hpp"
#include "core/present/message_text.hpp"

namespace {

bool isHelp(const std::string& arg) { return arg == "--help" || arg == "-h"; }

const char* const kCommands[] = {"eval",  "simulate",     "integrators", "accuracy", "derive", "render", "report",  "codegen",
                                 "check", "compare-laws", "check-answer", "exercise",    "grade",    "import", "export-urdf", "lesson", "help",   "version", "--version"};

// `lagrangelab`, `lagrangelab SCENE …` and `lagrangelab --screenshot …` open the window:
// no arguments, or a first argument that is no command but a scene file or an option.
bool opensWindow(int argc, char** argv) {
    if (argc < 2) return true;
    const std::string first = argv[1];
    if (isHelp(first)) return false;
    for (const char* c : kCommands)
        if (first == c) return false;
    return first.rfind("--", 0) == 0 || first.ends_with(".json") || first.ends_with(".lagrange") || std::filesystem::is_regular_file(first);
}

// The language of a usage error found before a command reads its options (no display, an
// unknown help topic): that of --lang when `args` give a good one, else the environment's.
ll::present::Language languageOf(ll::cli::Args args) {
    try {
        ll::cli::takePresentation(args, false);
    } catch (const ll::cli::UsageError&) {  // a bad --lang: the environment's language, for the error at hand
    }
    return ll::cli::presentation().language;
}

// f()'s exit code; its exceptions as one `error:` line each: bad input (exit 2) or a
// failure (exit 1).
template <class F>
int reportingErrors(F&& f) {
    using namespace ll::cli;
    try {
        return f();
    } catch (const ll::InputError& e) {
        for (const ll::Diagnostic& d : e.diagnostics())
            if (d.severity == ll::Severity::Error) std::cerr << ll::present::diagnosticText(d, presentation().language) << '\n';
        return 2;
    } catch (const UsageError& e) {
        std::cerr << usageErrorLine(e.message(), presentation().language) << '\n';
        return 2;
    } catch (const ll::MessageError& e) {  // ours (a file that cannot be saved): in the reader's language
        const ll::present::Language language = presentation().language;
        std::cerr << ll::present::messageText(ll::MessageId::ErrorLine, language) << ll::present::messageText(e.message(), language)
                  << '\n';
        return 1;
    } catch (const std::invalid_argument& e) {  // the core's or a library's English words, so English around them
        std::cerr << "error: " << e.what() << '\n';
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << '\n';
        return 1;
    }
}

}  // namespace

int main(int argc, char** argv) {
    using namespace ll::cli;
    const auto processStart = std::chrono::steady_clock::now();
    if (opensWindow(argc, argv)) {
        if (!hasDisplay()) {
            std::cerr << overviewUsage() << usageErrorLine(usageMessage(UsageId::NoDisplay), languageOf(Args(argv + 1, argv + argc)))
                      << '\n';
            return 2;
        }
        return reportingErrors([&] {
            Args args(argv + 1, argv + argc);
            takePresentation(args, false);
            return windowCommand(args, processStart);
        });
    }
    const std::string command = argv[1];
    Args args(argv + 2, argv + argc);
    // `lagrangelab COMMAND --help`: that command's usage, whatever else is given
    // (`help X --help` is X's usage, below).
    if (command != "help" && !commandUsage(command).empty() && std::any_of(args.begin(), args.end(), isHelp)) {
        std::fputs(commandUsage(command).c_str(), stdout);
        return 0;
    }
    if (command == "--version" || command == "version") {
        std::printf("lagrangelab %s\n", projectVersion());
        return 0;
    }
    if (isHelp(command) || command == "help") {
        // `help --help`: help's own usage.
        const std::string topic = command != "help" || args.empty() ? "" : isHelp(args[0]) ? "help" : args[0];
        const std::string usage = topic.empty() ? overviewUsage() : commandUsage(topic);
        if (usage.empty()) {
            const UsageMessage unknown = usageMessage(UsageId::HelpUnknownCommand, topic, commandNames());
            std::cerr << usageErrorLine(unknown, languageOf(args)) << '\n';
            return 2;
        }
        std::fputs(usage.c_str(), stdout);
        return 0;
    }
    return reportingErrors([&] {
        takePresentation(args, command == "codegen");
        if (command == "eval") return evalCommand(args);
        if (command == "simulate") return simulateCommand(args);
        if (command == "integrators") return integratorsCommand(args);
        if (command == "accuracy") return accuracyCommand(args);
        if (command == "derive") return deriveCommand(args);
        if (command == "render") return renderCommand(args);
        if (command == "report") return reportCommand(args);
        if (command == "codegen") return codegenCommand(args);
        if (command == "check") return checkCommand(args);
        if (command == "compare-laws") return compareLawsCommand(args);
        if (command == "check-answer") return checkAnswerCommand(args);
        if (command == "exercise") return exerciseCommand(args);
        if (command == "grade") return gradeCommand(args);
        if (command == "import") return importCommand(args);
        if (command == "export-urdf") return exportUrdfCommand(args);
        if (command == "lesson") return lessonCommand(args);
        std::cerr << usageErrorLine(usageMessage(UsageId::UnknownCommand, command), presentation().language) << "\n\n" << overviewUsage();
        return 2;
    });
}
