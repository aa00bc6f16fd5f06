// `lagrangelab derive SCENE [--format text|latex|json|pdf|svg|png] [--out FILE]
// [--steps 0-8] [--symbolic] [--numeric] [--timings]`: the course notes' procedure, step
// by step; pdf, svg and png typeset it (ui/derivation_pages) headless into --out.
#include <cstdio>
#include <iostream>

#include <QFileInfo>

#include "app/cli_options.hpp"
#include "app/command_usage.hpp"
#include "app/commands.hpp"
#include "app/scene_loading.hpp"
#include "app/offscreen_gui.hpp"
#include "core/pipeline/scene_derivation.hpp"
#include "ui/derivation_pages.hpp"

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
    const Options options(args, {"format", "steps", "out"}, {"symbolic", "numeric", "timings"});
    if (options.positional().size() != 1)
        throw UsageError(usageLine("derive"));
    const std::string format = options.text("format", "text");
    const bool typeset = format == "pdf" || format == "svg" || format == "png";
    if (format != "text" && format != "latex" && format != "json" && !typeset)
        throw UsageError("--format: expected text, latex, json, pdf, svg or png, got '" + format + "'");
    if (typeset && !options.has("out")) throw UsageError("--out: --format " + format + " writes a file; give --out FILE");
    if (!typeset && options.has("out")) throw UsageError("--out: only for --format pdf, svg or png (text, latex and json go to stdout)");
    if (typeset) {  // before the work: a file that cannot be written is known now
        const QFileInfo dir(QFileInfo(QString::fromStdString(options.text("out"))).absolutePath());
        if (!dir.isDir() || !dir.isWritable())
            throw UsageError("--out: cannot write '" + options.text("out") + "': " +
                             (dir.isDir() ? "the folder is not writable" : "no such folder"));
    }
    if (options.has("symbolic") && options.has("numeric")) throw UsageError("--symbolic and --numeric exclude each other");
    const Scene scene = loadSceneReportingWarnings(options.positional()[0]);
    const StepRange range = parseSteps(options.text("steps", "0-8"));

    DocumentRequest request;
    request.mode = options.has("symbolic") ? ParameterMode::Textbook
                   : options.has("numeric") ? ParameterMode::Numeric
                                            : ParameterMode::Parametric;
    request.firstStep = range.first;
    request.lastStep = range.last;
    request.format = typeset           ? DocumentFormat::Display
                     : format == "text"  ? DocumentFormat::Text
                     : format == "latex" ? DocumentFormat::Latex
                                         : DocumentFormat::Json;
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
    if (!typeset) {
        std::cout << derived.document;
        return 0;
    }
    const auto app = makeGuiApplication();
    if (!ui::mathFontsAvailable()) throw std::runtime_error("the Latin Modern fonts are missing: install fonts-lmodern");
    const ui::DerivationPages pages = ui::paginate(*derived.display);
    const QString out = QString::fromStdString(options.text("out"));
    std::string error;
    std::vector<QString> written;
    const bool ok = format == "pdf"   ? ui::writePdf(pages, out, error)
                    : format == "svg" ? ui::writeSvg(pages, out, error, &written)
                                      : ui::writePng(pages, out, error, &written);
    if (!ok) throw UsageError("--out: " + error);
    if (options.has("timings")) std::fprintf(stderr, "pages: %zu\n", pages.pages.size());
    if (written.size() > 1)
        for (const QString& file : written) std::fprintf(stderr, "wrote %s\n", file.toStdString().c_str());
    return 0;
}

}  // namespace ll::cli
