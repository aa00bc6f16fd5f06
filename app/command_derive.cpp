// `lagrangelab derive SCENE [--format text|latex|json] [--steps 0-8] [--symbolic]
// [--numeric] [--timings]`: the course notes' procedure, step by step.
#include <cstdio>
#include <iostream>

#include "app/cli_options.hpp"
#include "app/command_usage.hpp"
#include "app/commands.hpp"
#include "app/scene_loading.hpp"
#include "core/pipeline/scene_derivation.hpp"

namespace ll::cli {
namespace {

using namespace ll::symbolic;

struct StepRange {
    int first = 0, last = 8;
};

StepRange parseSteps(const std::string& text) {
    StepRange range;
    const size_t dash = text.find('-');
    try {
        range.first = std::stoi(text.substr(0, dash));
        range.last = dash == std::string::npos ? range.first : std::stoi(text.substr(dash + 1));
    } catch (const std::exception&) {
        throw UsageError("--steps: expected a step or a range such as 0-8, got '" + text + "'");
    }
    if (range.first < 0 || range.last > 8 || range.first > range.last)
        throw UsageError("--steps: steps are numbered 0 to 8, got '" + text + "'");
    return range;
}

}  // namespace

int deriveCommand(const Args& args) {
    const Options options(args, {"format", "steps"}, {"symbolic", "numeric", "timings"});
    if (options.positional().size() != 1)
        throw UsageError(usageLine("derive"));
    const std::string format = options.text("format", "text");
    if (format != "text" && format != "latex" && format != "json")
        throw UsageError("--format: expected text, latex or json, got '" + format + "'");
    if (options.has("symbolic") && options.has("numeric")) throw UsageError("--symbolic and --numeric exclude each other");
    const Scene scene = loadSceneReportingWarnings(options.positional()[0]);
    const StepRange range = parseSteps(options.text("steps", "0-8"));

    DocumentRequest request;
    request.mode = options.has("symbolic") ? ParameterMode::Textbook
                   : options.has("numeric") ? ParameterMode::Numeric
                                            : ParameterMode::Parametric;
    request.firstStep = range.first;
    request.lastStep = range.last;
    request.format = format == "text" ? DocumentFormat::Text : format == "latex" ? DocumentFormat::Latex : DocumentFormat::Json;
    const DerivedDocument derived = inSceneFile(options.positional()[0], [&] { return deriveDocument(scene, request); });

    if (options.has("timings")) {
        double total = 0;
        for (const StepTiming& step : derived.timings) {
            std::fprintf(stderr, "step %d (%s): %.3f ms\n", step.number, step.title.c_str(), 1e3 * step.seconds);
            total += step.seconds;
        }
        std::fprintf(stderr, "total: %.3f ms\n", 1e3 * total);
        std::fprintf(stderr, "printing: %.3f ms\n", 1e3 * derived.printSeconds);
    }
    for (const std::string& w : derived.warnings) std::cerr << "warning: " << w << '\n';
    std::cout << derived.document;
    return 0;
}

}  // namespace ll::cli
