#pragma once
// The derivation view's page (derivation_view.hpp): the shown step's general formula and
// its items typeset, each under a header that collapses it; a click picks an item or a
// cell, the context menu copies one as LaTeX. Used by DerivationView only.
#include <QApplication>
#include <QClipboard>
#include <QColor>
#include <QContextMenuEvent>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QWidget>
#include <algorithm>
#include <functional>
#include <vector>

#include "core/present/display_document.hpp"
#include "core/present/message_text.hpp"
#include "ui/paint/math_typesetter.hpp"

namespace ll::ui {

// An item's header: its left side as text (b11, g(q), T_2^0, β11(2) for the structured
// form's beta1_1_2), or "equation 1" for an equation of motion, whose left side is the
// whole row of B q̈ + C q̇ + g.
inline QString shownName(const present::DisplayItem& item) {
    if (item.quantity == present::Quantity::EquationOfMotion)
        return QCoreApplication::translate("ll::ui::DerivationView", "equation %1").arg(item.row + 1);
    if (item.quantity == present::Quantity::ClosedLoop)
        return QCoreApplication::translate("ll::ui::DerivationView", "closed loop %1").arg(item.row + 1);
    if (item.equation && item.equation->kind == present::DisplayKind::Equation && !item.equation->children.empty())
        return QString::fromStdString(present::renderDisplay(*item.equation->children[0], present::DisplayStyle::Text));
    return QString::fromStdString(item.name);
}

// The shown step: its general formula and items, each with a header that collapses it.
// Lines are typeset on first paint and kept until the zoom or the width changes.
class DerivationCanvas : public QWidget {
public:
    // An item (row < 0) or one cell of its matrix to draw a tinted background behind.
    struct Mark {
        int item = 0, row = -1, col = -1;
        QColor colour;
    };
    std::function<void(int item, int row, int col)> picked;  // a click on an item or one of its cells
    std::function<void(double top, double bottom)> reveal;   // scroll so that this band is seen
    int revealItem = -1, revealRow = -1, revealCol = -1;     // the item (or its cell) to reveal after the next paint

    explicit DerivationCanvas(QWidget* parent) : QWidget(parent) {
        setObjectName("derivation-canvas");
        setBackgroundRole(QPalette::Base);
        setAutoFillBackground(true);
    }

    void setMarks(std::vector<Mark> marks) {
        marks_ = std::move(marks);
        update();
    }

    void show(const present::DisplayStep* step, double zoom, present::Language language) {
        step_ = step;
        language_ = language;
        zoom_ = zoom;
        entries_.clear();
        if (step_)
            for (std::size_t i = 0; i < step_->items.size(); ++i) entries_.push_back({});
        relayout();
    }

    void setZoom(double zoom) {
        zoom_ = zoom;
        for (Entry& e : entries_) e.lines.clear();
        relayout();
    }

    void relayout() {
        for (Entry& e : entries_) e.lines.clear();
        formulaLines_.clear();
        setMinimumHeight(static_cast<int>(contentHeight()));
        update();
    }

    QString title(int index) const {
        if (!step_ || index < 0 || index >= static_cast<int>(step_->items.size())) return {};
        return shownName(step_->items[static_cast<std::size_t>(index)]);
    }

    QString latex(int index) const {
        if (!step_ || index < 0 || index >= static_cast<int>(step_->items.size())) return {};
        return QString::fromStdString(renderDisplay(*step_->items[static_cast<std::size_t>(index)].equation, present::DisplayStyle::Latex));
    }

protected:
    void resizeEvent(QResizeEvent*) override {
        if (std::abs(width() - laidOutWidth_) > 1) relayout();
    }

    void paintEvent(QPaintEvent* event) override {
        QPainter p(this);
        p.setRenderHint(QPainter::Antialiasing);
        p.setPen(palette().color(QPalette::Text));
        if (!step_) return;
        const double s = scale();
        double y = margin;
        QFont headerFont = font();
        const QFontMetricsF fm(headerFont);
        // The page's heading in the document's own language, as its title is.
        p.drawText(QPointF(margin, y + fm.ascent()),
                   QString::fromStdString(present::messageText(MessageId::DocumentStep, language_) + " " + std::to_string(step_->number) +
                                          ". " + present::messageText(step_->title, language_)));
        y += fm.height() * 1.2;
        p.setPen(palette().color(QPalette::PlaceholderText));
        if (step_->formula) {  // the general formula typeset, smaller than the results
            ensureFormula();
            for (const MathBox& line : formulaLines_) {
                paintMath(p, line, QPointF(margin, y + line.ascent * s * formulaScale), s * formulaScale);
                y += (line.height() + 0.3 * mathUnitsPerEm) * s * formulaScale;
            }
            y += fm.height() * 0.3;
        } else {
            p.drawText(QRectF(margin, y, width() - 2 * margin, fm.height() * 3), Qt::TextWordWrap,
                       QString::fromStdString(step_->formulaText));
            y += fm.boundingRect(QRectF(0, 0, width() - 2 * margin, 1e6), Qt::TextWordWrap, QString::fromStdString(step_->formulaText))
                     .height() +
                 fm.height() * 0.5;
        }
        for (std::size_t i = 0; i < entries_.size(); ++i) {
            Entry& e = entries_[i];
            const present::DisplayItem& item = step_->items[i];
            e.headerTop = y;
            e.lineTops.clear();
            // The item picked (or a link's marked entries): a tinted band behind it.
            if (!e.collapsed) ensureLines(e, item);
            for (const Mark& m : marks_)
                if (m.item == static_cast<int>(i) && m.row < 0) p.fillRect(QRectF(2, y, width() - 4, itemHeight(e, fm)), m.colour);
            p.setPen(palette().color(QPalette::Link));
            const QString head = (e.collapsed ? QString::fromUtf8("▸ ") : QString::fromUtf8("▾ ")) + shownName(item);
            p.drawText(QPointF(margin, y + fm.ascent()), head);
            if (!item.note.empty()) {  // what the name means (the structured form)
                const double x = margin + fm.horizontalAdvance(head + "  ");
                p.setPen(palette().color(QPalette::PlaceholderText));
                p.drawText(QPointF(x, y + fm.ascent()), fm.elidedText(QString::fromStdString(present::messageText(item.note, language_)),
                                                                      Qt::ElideRight, std::max(0.0, width() - margin - x)));
            }
            y += fm.height() * 1.1;
            if (e.collapsed) continue;
            ensureLines(e, item);
            p.setPen(palette().color(QPalette::Text));
            for (const MathBox& line : e.lines) {
                const double top = y, bottom = y + line.height() * s;
                e.lineTops.push_back(top);
                const QPointF origin(margin + indent, y + line.ascent * s);
                for (const Mark& m : marks_)  // a picked or marked cell of a matrix
                    if (m.item == static_cast<int>(i) && m.row >= 0)
                        for (const MathRegion& r : line.regions)
                            if (r.row == m.row && r.col == m.col)
                                p.fillRect(QRectF(origin + r.rect.topLeft() * s, r.rect.size() * s), m.colour);
                if (bottom >= event->rect().top() && top <= event->rect().bottom())  // paint only what is exposed
                    paintMath(p, line, origin, s, true);                             // each link's parameters in its colour
                y = bottom + 0.35 * mathUnitsPerEm * s;
            }
            y += 0.4 * mathUnitsPerEm * s;
        }
        if (std::abs(y + margin - minimumHeight()) > 1) setMinimumHeight(static_cast<int>(y + margin));
        if (revealItem >= 0 && revealItem < static_cast<int>(entries_.size()) && reveal) {
            const Entry& e = entries_[static_cast<std::size_t>(revealItem)];
            double top = e.headerTop, bottom = e.headerTop + itemHeight(e, fm);
            for (std::size_t l = 0; revealRow >= 0 && l < e.lines.size() && l < e.lineTops.size(); ++l)  // a cell: its line
                for (const MathRegion& r : e.lines[l].regions)
                    if (r.row == revealRow && r.col == revealCol) {
                        top = e.lineTops[l];
                        bottom = top + e.lines[l].height() * scale();
                        l = e.lines.size();
                        break;
                    }
            revealItem = -1;
            reveal(top, bottom);
        }
    }

    // A click on an item's triangle collapses or opens it; on its name or its formula it
    // picks the item, or the entry of its matrix under the pointer.
    void mousePressEvent(QMouseEvent* event) override {
        if (event->button() != Qt::LeftButton) return;
        const QPointF at = event->position();
        const int header = headerAt(at.y());
        if (header >= 0 && at.x() < margin + QFontMetricsF(font()).horizontalAdvance(QString::fromUtf8("▾ "))) {
            entries_[static_cast<std::size_t>(header)].collapsed = !entries_[static_cast<std::size_t>(header)].collapsed;
            update();
            return;
        }
        const int index = itemAt(at.y());
        if (index < 0 || !picked) return;
        const Entry& e = entries_[static_cast<std::size_t>(index)];
        const double s = scale();
        for (std::size_t l = 0; header < 0 && l < e.lines.size() && l < e.lineTops.size(); ++l) {
            const MathBox& line = e.lines[l];
            const QPointF origin(margin + indent, e.lineTops[l] + line.ascent * s);
            for (const MathRegion& r : line.regions)
                if (QRectF(origin + r.rect.topLeft() * s, r.rect.size() * s).contains(at)) {
                    picked(index, r.row, r.col);
                    return;
                }
        }
        picked(index, -1, -1);
    }

    void contextMenuEvent(QContextMenuEvent* event) override {
        const int index = itemAt(event->pos().y());
        if (index < 0) return;
        QMenu menu(this);
        menu.addAction(tr("Copy %1 as LaTeX").arg(shownName(step_->items[static_cast<std::size_t>(index)])),
                       [this, index] { QApplication::clipboard()->setText(latex(index)); });
        menu.exec(event->globalPos());
    }

private:
    struct Entry {
        bool collapsed = false;
        std::vector<MathBox> lines;
        std::vector<double> lineTops;  // where each line was painted last
        double headerTop = 0;
    };
    std::vector<Mark> marks_;

    // From the header to below the last line (its lines as laid out last, if any).
    double itemHeight(const Entry& e, const QFontMetricsF& fm) const {
        double h = fm.height() * 1.1;
        if (e.collapsed) return h;
        for (const MathBox& line : e.lines) h += (line.height() + 0.35 * mathUnitsPerEm) * scale();
        return h;
    }
    static constexpr double margin = 12, indent = 18;
    const present::DisplayStep* step_ = nullptr;
    present::Language language_ = present::Language::English;
    std::vector<Entry> entries_;
    double zoom_ = 1.0;
    int laidOutWidth_ = 0;

    double scale() const { return 15.0 * zoom_ / mathUnitsPerEm; }  // device px per layout unit

    static constexpr double formulaScale = 0.85;
    std::vector<MathBox> formulaLines_;

    void ensureFormula() {
        if (!formulaLines_.empty() || !step_ || !step_->formula) return;
        const double available = std::max(200.0, (width() - 2 * margin) / (scale() * formulaScale));
        formulaLines_ = layoutFormula(*step_->formula, available);
    }

    void ensureLines(Entry& e, const present::DisplayItem& item) {
        if (!e.lines.empty()) return;
        laidOutWidth_ = width();
        const double available = std::max(200.0, (width() - 2 * margin - indent) / scale());
        e.lines = layoutItem(item, available, language_);
    }

    double contentHeight() const { return 400; }  // grows on the first paint

    int headerAt(double y) const {
        const double h = QFontMetricsF(font()).height() * 1.1;
        for (std::size_t i = 0; i < entries_.size(); ++i)
            if (y >= entries_[i].headerTop && y < entries_[i].headerTop + h) return static_cast<int>(i);
        return -1;
    }
    int itemAt(double y) const {
        int found = -1;
        for (std::size_t i = 0; i < entries_.size(); ++i)
            if (y >= entries_[i].headerTop) found = static_cast<int>(i);
        return found;
    }
};

}  // namespace ll::ui
