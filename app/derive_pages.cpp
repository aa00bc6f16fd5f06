// The pages of `lagrangelab derive SCENE --format pdf|svg|png --out FILE`: the display
// document typeset headless (ui/derivation_pages). Runs in lagrangelab-gui only.
// A PDF is laid out and written while the document is still being shaped: this thread
// shapes (GiNaC, and its heap in huge pages: core/io/huge_page_heap.hpp), a second one
// paints the pages QPdfWriter writes, and writePdf's own layout thread feeds it.
#include <chrono>
#include <cstdio>
#include <exception>
#include <thread>

#include "app/commands.hpp"
#include "app/cli_options.hpp"
#include "app/offscreen_gui.hpp"
#include "core/model/exit_memory.hpp"
#include "core/symbolic/display_stream.hpp"
#include "ui/derivation_pages.hpp"

namespace ll::cli {
namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point since) { return std::chrono::duration<double>(Clock::now() - since).count(); }

int writePdfWhileDeriving(const DisplayDerivation& derive, const QString& out, bool timings) {
    const Disposing<symbolic::DisplayStream> streamOwner;  // its trees: left to the exit, as the derivation's are
    symbolic::DisplayStream& stream = *streamOwner;
    std::string error;
    bool written = false;
    int pageCount = 0;
    std::exception_ptr writerFailed;
    std::thread writer([&] {
        try {
            written = ui::writePdf(stream, out, error, {}, &pageCount);
        } catch (...) {
            writerFailed = std::current_exception();
        }
    });
    Clock::time_point shaped;
    try {
        dispose(derive(&stream));
        shaped = Clock::now();
    } catch (...) {
        stream.fail();  // the writer stops; nothing is saved
        writer.join();
        throw;
    }
    writer.join();
    if (writerFailed) std::rethrow_exception(writerFailed);
    if (!written) throw UsageError("--out: " + error);
    if (timings) {
        std::fprintf(stderr, "pdf laid out and written beside the shaping, finished %.3f ms after it\n", 1e3 * secondsSince(shaped));
        std::fprintf(stderr, "pages: %d\n", pageCount);
    }
    return 0;
}

}  // namespace

int writeDerivationPages(const DisplayDerivation& derive, const std::string& format, const std::string& outPath, bool timings) {
    const Clock::time_point startGui = Clock::now();
    const auto app = makeGuiApplication();
    if (!ui::mathFontsAvailable()) throw std::runtime_error("the Latin Modern fonts are missing: install fonts-lmodern");
    if (timings) std::fprintf(stderr, "fonts and Qt: %.3f ms\n", 1e3 * secondsSince(startGui));
    const QString out = QString::fromStdString(outPath);
    if (format == "pdf") return writePdfWhileDeriving(derive, out, timings);
    const std::shared_ptr<const symbolic::DisplayDocument> display = derive(nullptr);
    dispose(display);
    const Clock::time_point startLayout = Clock::now();
    const ui::DerivationPages pages = ui::paginate(*display);
    const double layoutSeconds = secondsSince(startLayout);
    const Clock::time_point startWrite = Clock::now();
    std::vector<QString> written;
    std::string error;
    const bool ok = format == "svg" ? ui::writeSvg(pages, out, error, &written) : ui::writePng(pages, out, error, &written);
    if (!ok) throw UsageError("--out: " + error);
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
