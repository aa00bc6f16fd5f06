#include "ui/paint/derivation_pages.hpp"

#include <QBuffer>
#include <QFileInfo>
#include <QImage>
#include <QImageWriter>
#include <QPainter>
#include <QPdfWriter>
#include <algorithm>
#include <cmath>

#include "core/io/atomic_file.hpp"
#include "core/present/message_text.hpp"
#include "ui/paint/svg_page.hpp"

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
        const bool fits =
            std::abs(estimate - maxWidth) < nearMargin ? prose(candidate, size, bold).width <= maxWidth : estimate <= maxWidth;
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

DerivationPages paginate(const present::DisplayDocument& document, const PageFormat& format) {
    DerivationPages pages;
    pages.format = format;
    pages.language = document.language;
    paginate(document, format, [&](std::vector<PlacedBox>&& page) { pages.pages.push_back(std::move(page)); });
    return pages;
}

namespace {

void paginateFrom(const present::DisplayDocument& document, const PageFormat& format, const PageSink& sink) {
    Composer c(format, sink);
    const double em = mathUnitsPerEm;
    // The document's own language (core/present/language.hpp), not the window's.
    const auto words = [&](const Message& m) { return present::messageText(m, document.language); };
    c.block(wrapped(QString::fromStdString(words(MessageId::DocumentModelTitle) + ": " + document.systemName), 1.5, c.width(), true), 0, 0,
            0.3 * em);
    c.block(wrapped(QString::fromStdString(words(MessageId::DocumentShorthand) +
                                           ": c_i = cos q_i, s_i = sin q_i, c12 = cos(q1 + q2); q̇, q̈ " +
                                           words(MessageId::DocumentJointVelocitiesAndAccelerations) + "."),
                    0.85, c.width()),
            0, 0.4 * em, 0.2 * em);
    if (!document.form.empty())
        c.block(wrapped(QString::fromStdString(words(MessageId::DocumentForm) + ": " + words(document.form) + " (" +
                                               words(document.formReason) + ")"),
                        0.85, c.width()),
                0, 0.2 * em, 0.2 * em);
    if (!document.remark.empty()) c.block(wrapped(QString::fromStdString(words(document.remark)), 0.85, c.width()), 0, 0.2 * em, 0.2 * em);
    const auto indented = [&](const MathBox& l) {
        MathBox out;
        hcat(out, l, em);
        return out;
    };
    for (const present::DisplayStep& s : document.steps) {
        const present::DisplayStep* step = &s;
        std::vector<MathBox> head =
            wrapped(QString::fromStdString(words(MessageId::DocumentStep) + " " + std::to_string(step->number) + ". " + words(step->title)),
                    1.2, c.width(), true);
        if (step->formula)  // the notes' general formula, typeset
            for (const MathBox& l : layoutFormula(*step->formula, (c.width() - em) / 0.9, 0.9)) head.push_back(indented(l));
        else
            for (const MathBox& l : wrapped(QString::fromStdString(step->formulaText), 0.85, c.width() - em)) head.push_back(indented(l));
        c.block(head, 0, 1.4 * em, 0.3 * em);
        for (const present::DisplayItem& it : step->items) {
            const present::DisplayItem* item = &it;
            std::vector<MathBox> lines = layoutItem(*item, c.width() - em, document.language);
            if (!item->note.empty()) {  // what a name means, beside it when it fits, else under it
                const QString meaning = QString::fromStdString(words(item->note));
                const MathBox note = layoutProse(meaning, 0.75);
                if (lines.size() == 1 && lines[0].width + 2 * em + note.width <= c.width() - em) hcat(lines[0], note, 2 * em);
                else
                    for (const MathBox& l : wrapped(meaning, 0.75, c.width() - 3 * em)) lines.push_back(indented(l));
            }
            c.block(lines, em, (item->note.empty() ? 0.7 : 0.35) * em, 0.45 * em);
        }
    }
    c.block(wrapped(QString::fromStdString(words(MessageId::DocumentActuation) + ": " + document.actuation), 0.9, c.width()), 0, 1.2 * em,
            0.2 * em);
    c.finish();
}

}  // namespace

void paginate(const present::DisplayDocument& document, const PageFormat& format, const PageSink& sink) {
    paginateFrom(document, format, sink);
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

bool writePdf(const present::DisplayDocument& document, const QString& path, std::string& error, const PageFormat& format, int* pageCount) {
    const DerivationPages pages = paginate(document, format);
    if (pageCount) *pageCount = static_cast<int>(pages.pages.size());
    return writePdf(pages, path, error);
}

bool writePdf(const DerivationPages& pages, const QString& path, std::string& error) {
    const PageFormat& format = pages.format;
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    {
        QPdfWriter pdf(&buffer);
        constexpr int dpi = 720;  // 10 device units per point: fine positions for text
        pdf.setResolution(dpi);
        pdf.setPageSize(QPageSize(QSizeF(format.widthPt, format.heightPt), QPageSize::Point));
        pdf.setPageMargins(QMarginsF(0, 0, 0, 0));
        pdf.setTitle(QString::fromStdString(present::messageText(MessageId::DocumentDerivationTitle, pages.language)));
        pdf.setCreator("LagrangeLab");
        QPainter painter(&pdf);
        for (std::size_t i = 0; i < pages.pages.size(); ++i) {
            if (i) pdf.newPage();
            paintBoxes(painter, pages.pages[i], format, dpi / 72.0);
        }
    }
    return save(path, bytes.toStdString(), error);
}

bool writeSvg(const DerivationPages& pages, const QString& path, std::string& error, std::vector<QString>* written) {
    SvgGlyphs glyphs;  // each outline made once for all the pages
    const double scale = 1.0 / (glyphs.ptPerDevice() * pages.format.unitsPerPt());
    const QSizeF size(pages.format.widthPt, pages.format.heightPt);
    for (std::size_t i = 0; i < pages.pages.size(); ++i) {
        MathMarks marks;
        for (const PlacedBox& b : pages.pages[i]) collectMarks(b.box, b.origin * scale, scale, marks);
        const QString file = pagePath(path, static_cast<int>(i));
        if (!save(file, svgPage(marks, size, present::messageText(MessageId::DocumentDerivationTitle, pages.language), glyphs), error))
            return false;
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
        // Black on white: a grey-scale page, a quarter of the pixels' bytes of RGB.
        QImage image(QSize(static_cast<int>(pages.format.widthPt * perPt), static_cast<int>(pages.format.heightPt * perPt)),
                     QImage::Format_Grayscale8);
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
        // Qt's quality 80 is zlib's level 1: a page written in a quarter of the default
        // level's time (12 against 50 ms for a full A4 page), its file about 15 % larger.
        QImageWriter writer(&buffer, "PNG");
        writer.setQuality(80);
        writer.write(image);
        const QString file = pagePath(path, static_cast<int>(i));
        if (!save(file, bytes.toStdString(), error)) return false;
        if (written) written->push_back(file);
    }
    return true;
}

}  // namespace ll::ui
