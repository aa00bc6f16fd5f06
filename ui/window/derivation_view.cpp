#include "ui/window/derivation_view.hpp"

#include "ui/window/relabel.hpp"

#include <QApplication>
#include <QClipboard>
#include <QContextMenuEvent>
#include <QBoxLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>
#include <algorithm>

#include <QSignalBlocker>
#include <functional>
#include <initializer_list>

#include "core/model/cancellation.hpp"
#include "core/pipeline/display_derivation.hpp"
#include "core/present/message_text.hpp"
#include "ui/paint/math_typesetter.hpp"

namespace ll::ui {

// An item's header: its left side as text (b11, g(q), T_2^0, β11(2) for the structured
// form's beta1_1_2), or "equation 1" for an equation of motion, whose left side is the
// whole row of B q̈ + C q̇ + g.
static QString shownName(const present::DisplayItem& item) {
    if (item.quantity == present::Quantity::EquationOfMotion)
        return QCoreApplication::translate("ll::ui::DerivationView", "equation %1").arg(item.row + 1);
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
        return QString::fromStdString(renderDisplay(*step_->items[static_cast<std::size_t>(index)].equation,
                                                    present::DisplayStyle::Latex));
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
                   QString::fromStdString(present::messageText(MessageId::DocumentStep, language_) + " " + std::to_string(step_->number) + ". " +
                                          present::messageText(step_->title, language_)));
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
            y += fm.boundingRect(QRectF(0, 0, width() - 2 * margin, 1e6), Qt::TextWordWrap,
                                 QString::fromStdString(step_->formulaText)).height() + fm.height() * 0.5;
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
                p.drawText(QPointF(x, y + fm.ascent()),
                           fm.elidedText(QString::fromStdString(present::messageText(item.note, language_)), Qt::ElideRight, std::max(0.0, width() - margin - x)));
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
                    paintMath(p, line, origin, s, true);  // each link's parameters in its colour
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

DerivationView::DerivationView(QWidget* parent) : QWidget(parent) {
    layout_ = new QBoxLayout(QBoxLayout::LeftToRight, this);
    auto* left = new QVBoxLayout;
    steps_ = new QListWidget(this);
    steps_->setMaximumWidth(260);  // filled with the steps of the derivation that is made
    left->addWidget(steps_);
    auto* buttons = new QHBoxLayout;
    previous_ = new QPushButton(this);
    next_ = new QPushButton(this);
    buttons->addWidget(previous_);
    buttons->addWidget(next_);
    left->addLayout(buttons);
    status_ = new QLabel(this);
    status_->setWordWrap(true);
    left->addWidget(status_);
    layout_->addLayout(left);
    scroll_ = new QScrollArea(this);
    scroll_->setWidgetResizable(true);
    canvas_ = new DerivationCanvas(scroll_);
    canvas_->picked = [this](int item, int row, int col) { emit entryPicked(step_ == 9 ? -1 : shownIndex_, item, row, col); };
    canvas_->reveal = [this](double top, double bottom) {
        const int mid = static_cast<int>(std::min(top + 40, (top + bottom) / 2));  // a long item: its first lines
        (void)bottom;
        scroll_->ensureVisible(0, mid, 0, std::max(20, scroll_->viewport()->height() / 2 - 10));  // about the middle
    };
    scroll_->setWidget(canvas_);
    layout_->addWidget(scroll_, 1);
    connect(steps_, &QListWidget::currentRowChanged, this, [this](int row) {
        if (row >= 0 && row < static_cast<int>(listed_.size())) showStep(listed_[static_cast<std::size_t>(row)]);
    });
    connect(previous_, &QPushButton::clicked, this, &DerivationView::previousStep);
    connect(next_, &QPushButton::clicked, this, &DerivationView::nextStep);
    (*new Relabel(this))([this] {
        previous_->setText(tr("Previous"));
        next_->setText(tr("Next"));
        showStatus();
        relist();
    });
}

// The list holds the steps of the document derived (a robot's 0–8, a typed Lagrangian's
// 0, 6, 7, 8 with their own titles), then the pose results as step 9.
QStringList DerivationView::listedSteps() const {
    QStringList rows;
    for (int i = 0; i < steps_->count(); ++i) rows << steps_->item(i)->text();
    return rows;
}

void DerivationView::relist() {
    std::vector<std::pair<int, QString>> rows;
    if (document_)
        for (const present::DisplayStep& s : document_->steps)
            rows.emplace_back(s.number, QString::fromStdString(present::messageText(s.title, document_->language)));
    if (rows.empty()) rows.emplace_back(0, tr("DH parameters"));
    if (pose_) rows.emplace_back(9, tr("Results at the teach pose"));
    std::vector<int> numbers;
    for (const auto& [n, title] : rows) numbers.push_back(n);
    bool retitled = false;  // the same steps in another language
    for (int i = 0; i < steps_->count() && i < static_cast<int>(rows.size()); ++i)
        retitled = retitled || steps_->item(i)->text() != tr("Step %1: %2").arg(rows[static_cast<std::size_t>(i)].first).arg(rows[static_cast<std::size_t>(i)].second);
    if (numbers != listed_ || retitled || steps_->count() != static_cast<int>(rows.size())) {
        const QSignalBlocker quiet(steps_);
        steps_->clear();
        for (const auto& [n, title] : rows) steps_->addItem(tr("Step %1: %2").arg(n).arg(title));
        listed_ = std::move(numbers);
    }
    const auto at = std::lower_bound(listed_.begin(), listed_.end(), step_);
    const int step = at == listed_.end() ? listed_.back() : *at;  // a step this system has not: the next it has
    const QSignalBlocker quiet(steps_);
    steps_->setCurrentRow(static_cast<int>(std::find(listed_.begin(), listed_.end(), step) - listed_.begin()));
    if (step != step_) {
        step_ = step;
        emit stepChanged(step_);
    }
}

// Narrow (a dock beside the 3D view): the step list goes above the page, a few rows
// high, so the typeset page gets the whole width; wide: the list sits at the left.
void DerivationView::resizeEvent(QResizeEvent* event) {
    const bool narrow = width() < 640;
    layout_->setDirection(narrow ? QBoxLayout::TopToBottom : QBoxLayout::LeftToRight);
    steps_->setMaximumWidth(narrow ? QWIDGETSIZE_MAX : 260);
    steps_->setMaximumHeight(narrow ? 4 * steps_->sizeHintForRow(0) + 2 * steps_->frameWidth() : QWIDGETSIZE_MAX);
    QWidget::resizeEvent(event);
}

DerivationView::~DerivationView() {
    derivations_.cancel();
    pool_.waitForDone();
}

void DerivationView::cancel() {
    derivations_.cancel();
    derivations_.request();  // a job that finishes anyway is stale: its result is dropped
    deriving_ = false;
}

void DerivationView::setScene(const ll::Scene& scene) {
    const int request = derivations_.request();
    NewestWins::Flag cancel = derivations_.begin();  // the newest call wins
    deriving_ = true;
    status_->setText(tr("Deriving…"));
    pool_.start([this, request, cancel, scene] {
        std::shared_ptr<const present::DisplayDocument> document;
        QString error;
        try {
            DocumentRequest r;
            r.cancel = cancel.get();
            document = deriveDisplay(scene, r).display;  // the form auto picks: structured for large robots
        } catch (const Cancelled&) {
            return;
        } catch (const std::exception& e) {
            error = QString::fromStdString(e.what());
        }
        // The widget waits for its workers before it dies, so `this` is alive.
        derivations_.deliver(this, request, [this, document, error] { accept(document, error); });
    });
}

void DerivationView::setDeriving() {
    derivations_.cancel();
    derivations_.request();
    deriving_ = true;
    status_->setText(tr("Deriving…"));
}

void DerivationView::setDerivation(std::shared_ptr<const present::DisplayDocument> document, const QString& error) {
    derivations_.cancel();
    derivations_.request();
    accept(std::move(document), error);
}

// What the derivation shown is, or why there is none.
void DerivationView::showStatus() {
    if (deriving_)
        status_->setText(tr("Deriving…"));
    else if (!document_ && error_.isEmpty())
        status_->setText(tr("No scene"));
    else if (!error_.isEmpty() || !document_)
        status_->setText(tr("Error: %1").arg(error_));
    else if (document_->form.empty())
        status_->setText(QString::fromStdString(document_->systemName));
    else
        status_->setText(tr("%1 (%2 form)").arg(QString::fromStdString(document_->systemName),
                                                document_->form.id == MessageId::FormStructured ? tr("structured") : tr("expanded")));
}

void DerivationView::accept(std::shared_ptr<const present::DisplayDocument> document, QString error) {
    deriving_ = false;
    error_ = error;
    if (document) document_ = std::move(document);
    showStatus();
    relist();
    refresh();
    emit derivationFinished();
}

void DerivationView::refresh() {
    const present::DisplayStep* shown = step_ == 9 ? pose_.get() : nullptr;
    shownIndex_ = -1;
    if (document_ && !shown)
        for (std::size_t i = 0; i < document_->steps.size(); ++i)
            if (document_->steps[i].number == step_) {
                shown = &document_->steps[i];
                shownIndex_ = static_cast<int>(i);
                break;
            }
    canvas_->show(shown, zoom_, document_ ? document_->language : present::Language::English);
    setMarks(marks_);
    previous_->setEnabled(step_ > listed_.front());
    next_->setEnabled(step_ < lastStep());
}

void DerivationView::setPoseResults(std::shared_ptr<const present::DisplayStep> step) {
    const bool had = pose_ != nullptr;
    pose_ = std::move(step);
    if (!pose_ && had && step_ == 9) showStep(8);
    relist();
    if (step_ == 9 || had != (pose_ != nullptr)) refresh();
}

void DerivationView::showStep(int step) {
    // The listed step at or after `step` (before it, past the last).
    const auto at = std::lower_bound(listed_.begin(), listed_.end(), step);
    step = at == listed_.end() ? listed_.back() : *at;
    const bool changed = step != step_;
    step_ = step;
    const int row = static_cast<int>(std::find(listed_.begin(), listed_.end(), step) - listed_.begin());
    if (steps_->currentRow() != row) {
        const QSignalBlocker quiet(steps_);
        steps_->setCurrentRow(row);
    }
    refresh();
    if (changed) emit stepChanged(step);
}

void DerivationView::nextStep() {
    const auto after = std::upper_bound(listed_.begin(), listed_.end(), step_);
    if (after != listed_.end()) showStep(*after);
}
void DerivationView::previousStep() {
    const auto at = std::lower_bound(listed_.begin(), listed_.end(), step_);
    if (at != listed_.begin()) showStep(*(at - 1));
}

void DerivationView::setPageOnly(bool on) {
    for (QWidget* w : std::initializer_list<QWidget*>{steps_, previous_, next_, status_}) w->setVisible(!on);
}

void DerivationView::setZoom(double zoom) {
    zoom_ = std::clamp(zoom, 0.25, 8.0);
    canvas_->setZoom(zoom_);
}

void DerivationView::setMarks(std::vector<Mark> marks) {
    marks_ = std::move(marks);
    std::vector<DerivationCanvas::Mark> here;
    for (const Mark& m : marks_)
        if (m.step == shownIndex_ && (shownIndex_ >= 0 || step_ == 9)) here.push_back({m.item, m.row, m.col, m.colour});
    canvas_->setMarks(std::move(here));
}

void DerivationView::showDocumentStep(int stepIndex, int item, int row, int col) {
    if (!document_ || stepIndex < 0 || stepIndex >= static_cast<int>(document_->steps.size())) return;
    if (document_->steps[static_cast<std::size_t>(stepIndex)].number != step_)
        showStep(document_->steps[static_cast<std::size_t>(stepIndex)].number);
    if (item >= 0) {
        canvas_->revealItem = item;
        canvas_->revealRow = row;
        canvas_->revealCol = col;
        canvas_->update();
    }
}

QString DerivationView::itemLatex(int index) const { return canvas_->latex(index); }

QString DerivationView::itemTitle(int index) const { return canvas_->title(index); }

}  // namespace ll::ui
