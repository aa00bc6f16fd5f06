#include "ui/window/derivation_panel.hpp"

#include <QFontDatabase>
#include <QLabel>
#include <QMouseEvent>
#include <QPlainTextEdit>
#include <QRegularExpression>
#include <QScrollBar>
#include <QTextBlock>

#include <algorithm>
#include <QVBoxLayout>

#include "core/present/message_text.hpp"
#include "ui/document/live_derivation.hpp"

namespace ll::ui {

DerivationPanel::DerivationPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    status_ = new QLabel(this);
    view_ = new QPlainTextEdit(this);
    view_->setReadOnly(true);
    view_->setLineWrapMode(QPlainTextEdit::NoWrap);
    QFont font = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    baseFont_ = font.pointSizeF() > 0 ? font.pointSizeF() : 10.0;
    view_->setFont(font);
    layout->addWidget(status_);
    layout->addWidget(view_, 1);
    view_->viewport()->installEventFilter(this);
}

namespace {

// Terminal columns before position `at` of a line (a combining dot takes none).
int columnAt(const QString& line, int at) {
    int columns = 0;
    for (int i = 0; i < at && i < line.size(); ++i) {
        const QChar c = line[i];
        if (c.isLowSurrogate() || c.category() == QChar::Mark_NonSpacing) continue;
        ++columns;
    }
    return columns;
}

// The position in `line` of terminal column `column`.
int positionOf(const QString& line, int column) {
    int columns = 0, i = 0;
    for (; i < line.size() && columns < column; ++i) {
        const QChar c = line[i];
        if (c.isLowSurrogate() || c.category() == QChar::Mark_NonSpacing) continue;
        ++columns;
    }
    while (i < line.size() && (line[i].isLowSurrogate() || line[i].category() == QChar::Mark_NonSpacing)) ++i;
    return i;
}

}  // namespace

bool DerivationPanel::eventFilter(QObject* watched, QEvent* event) {
    if (watched == view_->viewport() && event->type() == QEvent::MouseButtonRelease) {
        const auto* mouse = static_cast<QMouseEvent*>(event);
        if (mouse->button() == Qt::LeftButton && !view_->textCursor().hasSelection()) {
            const QTextCursor cursor = view_->cursorForPosition(mouse->position().toPoint());
            const int line = cursor.blockNumber(), column = columnAt(cursor.block().text(), cursor.positionInBlock());
            for (const present::TextSpan& s : spans_)
                if (s.line == line && column >= s.from && column < s.to) {
                    emit entryPicked(s.step, s.item, s.row, s.col);
                    break;
                }
        }
    }
    return QWidget::eventFilter(watched, event);
}

void DerivationPanel::setMarks(const std::vector<EntryMark>& marks) {
    QList<QTextEdit::ExtraSelection> selections;
    for (const EntryMark& m : marks)
        for (const present::TextSpan& s : spans_) {
            if (s.step != m.step || s.item != m.item || (m.row >= 0 && (s.row != m.row || s.col != m.col))) continue;
            const QTextBlock block = view_->document()->findBlockByNumber(s.line);
            if (!block.isValid()) continue;
            QTextEdit::ExtraSelection selection;
            selection.format.setBackground(m.colour);
            selection.cursor = QTextCursor(block);
            selection.cursor.setPosition(block.position() + positionOf(block.text(), s.from));
            selection.cursor.setPosition(block.position() + positionOf(block.text(), std::min<int>(s.to, 1 << 16)),
                                         QTextCursor::KeepAnchor);
            selections.append(selection);
        }
    view_->setExtraSelections(selections);
}

void DerivationPanel::showItem(int step, int item) {
    for (const present::TextSpan& s : spans_)
        if (s.step == step && s.item == item) {
            const QTextBlock block = view_->document()->findBlockByNumber(s.line);
            if (!block.isValid()) return;
            view_->setTextCursor(QTextCursor(block));
            view_->ensureCursorVisible();
            return;
        }
}

void DerivationPanel::setDeriving() {
    busy_ = true;
    status_->setText(tr("Deriving…"));
}

void DerivationPanel::setDerivation(const DerivationResult& result) {
    busy_ = false;
    if (result.stopped) {
        status_->setText(tr("Derivation stopped: the model is being edited"));
        return;
    }
    if (!result.error.isEmpty()) {
        status_->setText(tr("The derivation stopped: %1").arg(result.error.trimmed()));
    } else {
        status_->setText(tr("Derived in %1 ms").arg(result.seconds * 1000, 0, 'f', 0));
        const int bar = view_->verticalScrollBar()->value();
        view_->setPlainText(result.text);
        spans_ = result.textSpans;
        readHeadings(result.display ? result.display->language : present::Language::English);
        view_->verticalScrollBar()->setValue(bar);
        showStep(step_);          // or the next step this derivation has
        emit stepChanged(step_);  // the count may have changed
    }
    emit derived();
}

// The steps the text has ("Step N." headings, in order): a robot's 0–8, a typed Lagrangian's own.
void DerivationPanel::readHeadings(present::Language language) {
    // "Step N." in the document's language (Trin N. in Danish).
    const QString stepWord = QString::fromStdString(present::messageText(MessageId::DocumentStep, language));
    const QRegularExpression heading("^" + QRegularExpression::escape(stepWord) + " (\\d+)\\.");
    steps_.clear();
    headingBlocks_.clear();
    for (QTextBlock block = view_->document()->begin(); block.isValid(); block = block.next())
        if (const QRegularExpressionMatch m = heading.match(block.text()); m.hasMatch()) {
            steps_.push_back(m.captured(1).toInt());
            headingBlocks_.push_back(block.blockNumber());
        }
    if (steps_.empty()) steps_ = headingBlocks_ = {0};
}

void DerivationPanel::nextStep() {
    const auto after = std::upper_bound(steps_.begin(), steps_.end(), step_);
    if (after != steps_.end()) showStep(*after);
}

void DerivationPanel::previousStep() {
    const auto at = std::lower_bound(steps_.begin(), steps_.end(), step_);
    if (at != steps_.begin()) showStep(*(at - 1));
}

void DerivationPanel::showStep(int n) {
    auto at = std::lower_bound(steps_.begin(), steps_.end(), n);  // the one at or after n (the last, past it)
    if (at == steps_.end()) --at;
    n = *at;
    QTextCursor cursor(view_->document()->findBlockByNumber(headingBlocks_[static_cast<std::size_t>(at - steps_.begin())]));
    view_->moveCursor(QTextCursor::End);
    view_->setTextCursor(cursor);
    view_->ensureCursorVisible();
    if (n != step_) {
        step_ = n;
        emit stepChanged(n);
    }
}

void DerivationPanel::setZoom(double factor) {
    QFont font = view_->font();
    font.setPointSizeF(baseFont_ * std::clamp(factor, 0.25, 8.0));
    view_->setFont(font);
}

QString DerivationPanel::text() const { return view_->toPlainText(); }

}  // namespace ll::ui
