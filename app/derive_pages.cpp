// The pages of `lagrangelab derive SCENE --format pdf|svg|png --out FILE`: the display
// document typeset headless (ui/derivation_pages).
#include <chrono>
#include <cstdio>

#include "app/commands.hpp"
#include "app/cli_options.hpp"
#include "app/offscreen_gui.hpp"
#include "ui/paint/derivation_pages.hpp"

namespace ll::cli {
namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point since) { return std::chrono::duration<double>(Clock::now() - since).count(); }

}  // namespace

int writeDerivationPages(const present::DisplayDocument& display, const std::string& format, const std::string& outPath, bool timings) {
    const Clock::time_point startGui = Clock::now();
    const auto app = makeGuiApplication();
    if (!ui::mathFontsAvailable()) throw std::runtime_error("the Latin Modern fonts are missing: install fonts-lmodern");
    if (timings) std::fprintf(stderr, "fonts and Qt: %.3f ms\n", 1e3 * secondsSince(startGui));
    const QString out = QString::fromStdString(outPath);
    const Clock::time_point startLayout = Clock::now();
    const ui::DerivationPages pages = ui::paginate(display);
    const double layoutSeconds = secondsSince(startLayout);
    const Clock::time_point startWrite = Clock::now();
    std::vector<QString> written;
    std::string error;
    const bool ok = format == "pdf"   ? ui::writePdf(pages, out, error)
                    : format == "svg" ? ui::writeSvg(pages, out, error, &written)
                                      : ui::writePng(pages, out, error, &written);
    if (!ok) throw UsageError(UsageId::OptionRefused, "out", error);  // ui's words
    if (timings) {
        std::fprintf(stderr, "layout into pages: %.3f ms\n", 1e3 * layoutSeconds);
        std::fprintf(stderr, "writing %s: %.3f ms\n", format.c_str(), 1e3 * secondsSince(startWrite));
        std::fprintf(stderr, "pages: %zu\n", pages.pages.size());
    }
    if (written.size() > 1)
        for (const QString& file : written) std::fprintf(stderr, "wrote %s\n", file.toStdString().c_str());
    if (const auto older = ui::pagesBeyond(out, static_cast<int>(written.size())); !older.empty())
        std::fprintf(stderr, "note: %zu page file%s of an earlier, longer export remain%s beside %s, not rewritten and not deleted: %s\n",
                     older.size(), older.size() == 1 ? "" : "s", older.size() == 1 ? "s" : "", written.size() == 1 ? "it" : "these",
                     ui::fileNameRange(older).toStdString().c_str());
    return 0;
}

}  // namespace ll::cli
