#include "ui/derivation_pages.hpp"

#include <QBuffer>
#include <QFileInfo>
#include <QImage>
#include <QPainter>
#include <QPdfWriter>
#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>

#include "core/io/atomic_file.hpp"
#include "ui/svg_page.hpp"

namespace ll::ui {
namespace {

// Bold prose (titles) is text only; the rest sets the symbols it names as math
// (layoutProse: "depends on q1, q2" with q₁, q₂).
MathBox prose(const QString& text, double size, bool bold) { return bold ? layoutText(text, size, true) : layoutProse(text, size); }

// Prose broken into lines of at most maxWidth units at spaces. Whether the next word
// still fits is judged from the widths of the words and the space (each measured once and
// cached: words recur across a derivation's notes); only a line that ends within half an
// em of the margin is shaped whole to decide, so the breaks are those of shaping every
// candidate line (kerning across a space moves a line's end by far less), without
// shaping a paragraph of n words n times.
std::vector<MathBox> wrapped(const QString& text, double size, double maxWidth, bool bold = false) {
    std::vector<MathBox> lines;
    const double space = layoutText(QStringLiteral("a b"), size, bold).width - layoutText(QStringLiteral("ab"), size, bold).width;
    const double nearMargin = 0.5 * mathUnitsPerEm * size;
    QString line;
    double lineWidth = 0;  // as the words add up
    for (const QString& w : text.split(' ', Qt::SkipEmptyParts)) {
        const double wordWidth = prose(w, size, bold).width;
        if (line.isEmpty()) {
            line = w;
            lineWidth = wordWidth;
            continue;
        }
        const double estimate = lineWidth + space + wordWidth;
        const QString candidate = line + ' ' + w;
        const bool fits = std::abs(estimate - maxWidth) < nearMargin ? prose(candidate, size, bold).width <= maxWidth
                                                                      : estimate <= maxWidth;
        if (fits) {
            line = candidate;
            lineWidth = estimate;
        } else {
            lines.push_back(prose(line, size, bold));
            line = w;
            lineWidth = wordWidth;
        }
    }
    if (!line.isEmpty()) lines.push_back(prose(line, size, bold));
    return lines;
}

class Composer {
public:
    Composer(const PageFormat& format, const PageSink& sink) : sink_(sink) {
        const double u = format.unitsPerPt();
        width_ = (format.widthPt - 2 * format.marginPt) * u;
        bottom_ = (format.heightPt - format.marginPt) * u;
        left_ = top_ = format.marginPt * u;
        y_ = top_;
    }
    double width() const { return width_; }
    void finish() { sink_(std::move(page_)); }

    // A block of lines kept together on one page when it fits one.
    void block(const std::vector<MathBox>& lines, double indent, double spaceBefore, double lineGap) {
        double height = 0;
        for (const MathBox& l : lines) height += l.height() + lineGap;
        y_ += spaceBefore;
        if (y_ + height > bottom_ && y_ > top_ + spaceBefore && height <= bottom_ - top_) newPage();
        for (const MathBox& l : lines) {
            if (y_ + l.height() > bottom_ && y_ > top_) newPage();
            y_ += l.ascent;
            page_.push_back({l, QPointF(left_ + indent, y_)});
            y_ += l.descent + lineGap;
        }
    }

private:
    const PageSink& sink_;
    std::vector<PlacedBox> page_;
    double width_ = 0, bottom_ = 0, left_ = 0, top_ = 0, y_ = 0;
    void newPage() {
        sink_(std::move(page_));
        page_ = {};
        y_ = top_;
    }
};

}  // namespace

DerivationPages paginate(const symbolic::DisplayDocument& document, const PageFormat& format) {
    DerivationPages pages;
    pages.format = format;
    paginate(document, format, [&](std::vector<PlacedBox>&& page) { pages.pages.push_back(std::move(page)); });
    return pages;
}

namespace {

// What paginate reads: a finished document, or a stream that grows while it is read.
struct CompleteDocument {
    const symbolic::DisplayDocument& document;
    const symbolic::DisplayDocument& head() const { return document; }
    const symbolic::DisplayStep* step(std::size_t i) const { return i < document.steps.size() ? &document.steps[i] : nullptr; }
    const symbolic::DisplayItem* item(std::size_t i, std::size_t j) const {
        return j < document.steps[i].items.size() ? &document.steps[i].items[j] : nullptr;
    }
    std::string actuation() const { return document.actuation; }
};

struct StreamFailed {};  // the shaping thread failed: its own error is the one to report

struct GrowingDocument {
    symbolic::DisplayStream& stream;
    const symbolic::DisplayDocument& head() const {
        if (const symbolic::DisplayDocument* h = stream.head()) return *h;
        throw StreamFailed{};
    }
    const symbolic::DisplayStep* step(std::size_t i) const { return checked(stream.step(i)); }
    const symbolic::DisplayItem* item(std::size_t i, std::size_t j) const { return checked(stream.item(i, j)); }
    std::string actuation() const {
        std::string a = stream.actuation();
        if (stream.failed()) throw StreamFailed{};
        return a;
    }
    template <class T>
    T* checked(T* p) const {
        if (!p && stream.failed()) throw StreamFailed{};
        return p;
    }
};

template <class Source>
void paginateFrom(const Source& source, const PageFormat& format, const PageSink& sink) {
    Composer c(format, sink);
    const double em = mathUnitsPerEm;
    const symbolic::DisplayDocument& document = source.head();
    c.block(wrapped(QString::fromStdString("Euler–Lagrange model: " + document.systemName), 1.5, c.width(), true), 0, 0, 0.3 * em);
    c.block(wrapped("Shorthand: c_i = cos q_i, s_i = sin q_i, c12 = cos(q1 + q2); q̇, q̈ the joint velocities and "
                    "accelerations.",
                    0.85, c.width()),
            0, 0.4 * em, 0.2 * em);
    if (!document.form.empty())
        c.block(wrapped(QString::fromStdString("Form: " + document.form + " (" + document.formReason + ")"), 0.85, c.width()), 0,
                0.2 * em, 0.2 * em);
    const auto indented = [&](const MathBox& l) {
        MathBox out;
        hcat(out, l, em);
        return out;
    };
    for (std::size_t i = 0; const symbolic::DisplayStep* step = source.step(i); ++i) {
        std::vector<MathBox> head = wrapped(QString("Step %1. %2").arg(step->number).arg(QString::fromStdString(step->title)),
                                            1.2, c.width(), true);
        if (step->formula)  // the notes' general formula, typeset
            for (const MathBox& l : layoutFormula(*step->formula, (c.width() - em) / 0.9, 0.9)) head.push_back(indented(l));
        else
            for (const MathBox& l : wrapped(QString::fromStdString(step->formulaText), 0.85, c.width() - em)) head.push_back(indented(l));
        c.block(head, 0, 1.4 * em, 0.3 * em);
        for (std::size_t j = 0; const symbolic::DisplayItem* item = source.item(i, j); ++j) {
            std::vector<MathBox> lines = layoutItem(*item->equation, item->name, c.width() - em);
            if (!item->note.empty()) {  // what a name means, beside it when it fits, else under it
                const MathBox note = layoutProse(QString::fromStdString(item->note), 0.75);
                if (lines.size() == 1 && lines[0].width + 2 * em + note.width <= c.width() - em)
                    hcat(lines[0], note, 2 * em);
                else
                    for (const MathBox& l : wrapped(QString::fromStdString(item->note), 0.75, c.width() - 3 * em)) lines.push_back(indented(l));
            }
            c.block(lines, em, (item->note.empty() ? 0.7 : 0.35) * em, 0.45 * em);
        }
    }
    c.block(wrapped(QString::fromStdString("Actuation: " + source.actuation()), 0.9, c.width()), 0, 1.2 * em, 0.2 * em);
    c.finish();
}

}  // namespace

void paginate(const symbolic::DisplayDocument& document, const PageFormat& format, const PageSink& sink) {
    paginateFrom(CompleteDocument{document}, format, sink);
}

namespace {

void paintBoxes(QPainter& painter, const std::vector<PlacedBox>& page, const PageFormat& format, double devicePerPt) {
    const double scale = devicePerPt / format.unitsPerPt();
    painter.setPen(Qt::black);
    for (const PlacedBox& b : page) paintMath(painter, b.box, b.origin * scale, scale);
}

}  // namespace

void paintPage(QPainter& painter, const DerivationPages& pages, int index, double devicePerPt) {
    paintBoxes(painter, pages.pages.at(static_cast<std::size_t>(index)), pages.format, devicePerPt);
}

namespace {

bool save(const QString& path, const std::string& bytes, std::string& error) {
    try {
        saveFileAtomically(path.toStdString(), bytes, Backup::None);
        return true;
    } catch (const std::exception& e) {
        error = e.what();
        return false;
    }
}

QString pagePath(const QString& path, int page) {
    if (page == 0) return path;
    const QFileInfo info(path);
    const QString suffix = info.suffix().isEmpty() ? QString() : "." + info.suffix();
    return info.path() + "/" + info.completeBaseName() + QString("-%1").arg(page + 1) + suffix;
}

}  // namespace

namespace {

struct Cancelled {};  // the writer has stopped: lay out no more pages

// The PDF of the pages `next` hands out in order (false: no more); its painting runs on
// the calling thread.
template <typename NextPage>
bool writePdfOf(const PageFormat& format, NextPage&& next, const QString& path, std::string& error) {
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    {
        QPdfWriter pdf(&buffer);
        constexpr int dpi = 720;  // 10 device units per point: fine positions for text
        pdf.setResolution(dpi);
        pdf.setPageSize(QPageSize(QSizeF(format.widthPt, format.heightPt), QPageSize::Point));
        pdf.setPageMargins(QMarginsF(0, 0, 0, 0));
        pdf.setTitle("Euler–Lagrange derivation");
        pdf.setCreator("LagrangeLab");
        QPainter painter(&pdf);
        std::vector<PlacedBox> page;
        for (int i = 0; next(page); ++i) {
            if (i) pdf.newPage();
            paintBoxes(painter, page, format, dpi / 72.0);
        }
    }
    return save(path, bytes.toStdString(), error);
}

template <class Source>
bool writePdfFrom(const Source& source, const QString& path, std::string& error, const PageFormat& format, int* pageCount) {
    // Layout and QPdfWriter each take about as long for a large robot (the Panda: 0.12 s and
    // 0.19 s): a second thread lays out page k+1 while this one paints page k.
    std::mutex mutex;
    std::condition_variable changed;
    std::deque<std::vector<PlacedBox>> ready;
    bool laidOut = false, stop = false, streamFailed = false;
    std::exception_ptr failure;
    // Written pages go back to the layout thread, which frees them (outside the lock) and
    // reuses their memory: it is that thread's malloc arena, and freeing it from this
    // thread took the arena's lock while layout allocated in it (each thread ran at
    // half speed).
    std::vector<std::vector<PlacedBox>> written;
    std::thread layout([&] {
        bool shapingFailed = false;
        std::exception_ptr error;
        try {
            paginateFrom(source, format, [&](std::vector<PlacedBox>&& page) {
                std::vector<std::vector<PlacedBox>> done;
                {
                    std::lock_guard lock(mutex);
                    if (stop) throw Cancelled{};
                    ready.push_back(std::move(page));
                    done.swap(written);
                    changed.notify_one();
                }
            });
        } catch (const Cancelled&) {
        } catch (const StreamFailed&) {
            shapingFailed = true;
        } catch (...) {
            error = std::current_exception();
        }
        std::lock_guard lock(mutex);  // what the writing thread reads under it
        streamFailed = shapingFailed;
        failure = error;
        laidOut = true;
        changed.notify_one();
    });
    struct Join {  // the layout thread ends before anything it uses goes, even on a throw
        std::thread& thread;
        std::mutex& mutex;
        bool& stop;
        ~Join() {
            {
                std::lock_guard lock(mutex);
                stop = true;
            }
            thread.join();
        }
    } join{layout, mutex, stop};
    int pages = 0;
    const bool ok = writePdfOf(
        format,
        [&](std::vector<PlacedBox>& page) {
            std::unique_lock lock(mutex);
            changed.wait(lock, [&] { return !ready.empty() || laidOut; });
            if (failure) std::rethrow_exception(failure);  // before anything is saved: no half file
            if (streamFailed) throw StreamFailed{};
            if (ready.empty()) return false;
            if (!page.empty()) written.push_back(std::move(page));
            page = std::move(ready.front());
            ready.pop_front();
            ++pages;
            return true;
        },
        path, error);
    if (pageCount) *pageCount = pages;
    return ok;
}

}  // namespace

bool writePdf(const symbolic::DisplayDocument& document, const QString& path, std::string& error, const PageFormat& format,
              int* pageCount) {
    return writePdfFrom(CompleteDocument{document}, path, error, format, pageCount);
}

bool writePdf(symbolic::DisplayStream& stream, const QString& path, std::string& error, const PageFormat& format, int* pageCount) {
    try {
        return writePdfFrom(GrowingDocument{stream}, path, error, format, pageCount);
    } catch (const StreamFailed&) {  // nothing saved
        error = "the derivation stopped before its pages were complete";
        return false;
    }
}

bool writeSvg(const DerivationPages& pages, const QString& path, std::string& error, std::vector<QString>* written) {
    SvgGlyphs glyphs;  // each outline made once for all the pages
    const double scale = 1.0 / (glyphs.ptPerDevice() * pages.format.unitsPerPt());
    const QSizeF size(pages.format.widthPt, pages.format.heightPt);
    for (std::size_t i = 0; i < pages.pages.size(); ++i) {
        MathMarks marks;
        for (const PlacedBox& b : pages.pages[i]) collectMarks(b.box, b.origin * scale, scale, marks);
        const QString file = pagePath(path, static_cast<int>(i));
        if (!save(file, svgPage(marks, size, "Euler–Lagrange derivation", glyphs), error)) return false;
        if (written) written->push_back(file);
    }
    return true;
}

std::vector<QString> pagesBeyond(const QString& path, int pageCount) {
    std::vector<QString> files;
    for (int i = std::max(pageCount, 1);; ++i) {
        const QString file = pagePath(path, i);
        if (!QFileInfo::exists(file)) return files;
        files.push_back(file);
    }
}

QString fileNameRange(const std::vector<QString>& files) {
    if (files.empty()) return {};
    const QString first = QFileInfo(files.front()).fileName();
    return files.size() == 1 ? first : first + " … " + QFileInfo(files.back()).fileName();
}

bool writePng(const DerivationPages& pages, const QString& path, std::string& error, std::vector<QString>* written, double dpi) {
    const double perPt = dpi / 72.0;
    for (std::size_t i = 0; i < pages.pages.size(); ++i) {
        QImage image(QSize(static_cast<int>(pages.format.widthPt * perPt), static_cast<int>(pages.format.heightPt * perPt)),
                     QImage::Format_RGB32);
        image.fill(Qt::white);
        {
            QPainter painter(&image);
            painter.setRenderHint(QPainter::Antialiasing);
            painter.setRenderHint(QPainter::TextAntialiasing);
            // Shaped at ten device units per point as the PDF and SVG are, then scaled to
            // the image: shaped at the image's own pixel size, a glyph's advance is
            // rounded to whole pixels and a line of prose came out about 1 % longer or
            // shorter than in the PDF.
            constexpr double shapedPerPt = 10;
            painter.scale(perPt / shapedPerPt, perPt / shapedPerPt);
            paintPage(painter, pages, static_cast<int>(i), shapedPerPt);
        }
        QByteArray bytes;
        QBuffer buffer(&bytes);
        buffer.open(QIODevice::WriteOnly);
        image.save(&buffer, "PNG");
        const QString file = pagePath(path, static_cast<int>(i));
        if (!save(file, bytes.toStdString(), error)) return false;
        if (written) written->push_back(file);
    }
    return true;
}

}  // namespace ll::ui
