// `lagrangelab derive SCENE [--format text|latex|json|pdf|svg|png] [--out FILE]
// [--steps 0-9] [--symbolic] [--numeric] [--timings] [--form auto|structured|expanded]
// [--entry B11,C23,g4] [--verify]`: the course notes' procedure, step by step, expanded or
// structured (derivation_forms.hpp); pdf, svg and png typeset the same form (auto:
// expanded when cheap, else structured) headless into --out (app/derive_pages.cpp).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <unistd.h>

#include "app/cli_options.hpp"
#include "app/command_usage.hpp"
#include "app/commands.hpp"
#include "app/output_file.hpp"
#include "app/scene_loading.hpp"
#include "core/io/atomic_file.hpp"
#include "core/model/message_error.hpp"
#include "core/pipeline/derivation_forms.hpp"
#include "core/pipeline/display_derivation.hpp"
#include "core/pipeline/scene_derivation.hpp"

namespace ll::cli {
namespace {

using namespace ll::symbolic;
using present::DocumentFormat;

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
        throw UsageError(UsageId::StepsExpected, text);
    }
    if (range.first < 0 || range.last > symbolic::lastDerivationStep || range.first > range.last) throw UsageError(UsageId::StepsOutOfRange, text);
    return range;
}

// --timings (when asked) and the warnings, on stderr.
void report(const DerivedDocument& derived, bool timings) {
    if (timings) {
        double total = 0;
        for (const StepTiming& step : derived.timings) {
            std::fprintf(stderr, "step %d (%s): %.3f ms\n", step.number, step.title.c_str(), 1e3 * step.seconds);
            total += step.seconds;
        }
        std::fprintf(stderr, "total: %.3f ms\n", 1e3 * total);
        std::fprintf(stderr, "printing: %.3f ms\n", 1e3 * derived.printSeconds);
    }
    for (const std::string& w : derived.warnings) std::cerr << "warning: " << w << '\n';
}

}  // namespace

int deriveCommand(const Args& args) {
    const Options options(args, {"format", "steps", "out", "form", "entry"}, {"symbolic", "numeric", "timings", "verify"});
    if (options.positional().size() != 1) throw UsageError(usageLine("derive"));
    const std::string format = options.text("format", "text");
    const bool typeset = format == "pdf" || format == "svg" || format == "png";
    if (format != "text" && format != "latex" && format != "json" && !typeset)
        throw UsageError(UsageId::ExpectedOneOf, "format", "text, latex, json, pdf, svg", "png", format);
    if (typeset && !options.has("out")) throw UsageError(UsageId::FormatWritesFile, format);
    if (options.has("out")) requireWritableOutputFile(options.text("out"));  // before the work
    if (options.has("symbolic") && options.has("numeric")) throw UsageError(UsageId::ExcludeEachOther, "symbolic", "numeric");
    const std::string form = options.text("form", "auto");
    if (form != "auto" && form != "structured" && form != "expanded")
        throw UsageError(UsageId::ExpectedOneOf, "form", "auto, structured", "expanded", form);
    const Scene scene = loadSceneReportingWarnings(options.positional()[0]);
    const StepRange range = parseSteps(options.text("steps", "0-9"));

    DocumentRequest request;
    request.mode = options.has("symbolic")  ? ParameterMode::Textbook
                   : options.has("numeric") ? ParameterMode::Numeric
                                            : ParameterMode::Parametric;
    request.firstStep = range.first;
    request.presentation = presentation();
    request.lastStep = range.last;
    request.format = format == "text" ? DocumentFormat::Text : format == "latex" ? DocumentFormat::Latex : DocumentFormat::Json;
    const DerivationForm chosenForm = form == "structured" ? DerivationForm::Structured
                                      : form == "expanded" ? DerivationForm::Expanded
                                                           : DerivationForm::Auto;
    if (typeset && (options.has("entry") || options.has("verify")))  // the typeset pages show the form auto (or --form) picks
        throw UsageError(UsageId::TypesetWholeDerivations, format);
    const bool timings = options.has("timings");
    if (typeset) {
        request.forPages = true;  // long sums built as the pages cut them
        const DerivedDocument derived = inSceneFile(options.positional()[0], [&] { return deriveDisplay(scene, request, chosenForm); });
        report(derived, timings);
        return writeDerivationPages(*present::localizedDocument(*derived.display, presentation()), format, options.text("out"), timings);
    }
    FormRequest formRequest;
    formRequest.document = request;
    formRequest.form = chosenForm;
    formRequest.verify = options.has("verify");
    if (options.has("entry")) {
        const std::string list = options.text("entry");
        for (std::size_t start = 0; start <= list.size();) {
            const std::size_t end = std::min(list.find(',', start), list.size());
            formRequest.entries.push_back(list.substr(start, end - start));
            start = end + 1;
        }
    }
    const FormDocument result = inSceneFile(options.positional()[0], [&] {
        try {
            return deriveInForm(scene, formRequest);
        } catch (const MessageError& e) {  // a bad --entry, in the core's words
            throw UsageError(e.message());
        }
    });
    for (const std::string& line : result.verification) std::cerr << "verify: " << line << '\n';
    report(result.derived, timings);
    if (options.has("out"))  // written whole or not at all, as every file the program writes
        saveFileAtomically(options.text("out"), result.derived.document, Backup::None);
    else std::cout << result.derived.document;
    return 0;
}

}  // namespace ll::cli
