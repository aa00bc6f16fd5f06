#include "ui/derivation_panel.hpp"

#include <QFontDatabase>
#include <QLabel>
#include <QPlainTextEdit>
#include <QRegularExpression>
#include <QScrollBar>
#include <QTextBlock>
#include <QVBoxLayout>

#include "ui/live_derivation.hpp"

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
        view_->verticalScrollBar()->setValue(bar);
        if (step_ > 0) showStep(step_);
    }
    emit derived();
}

void DerivationPanel::showStep(int n) {
    n = std::clamp(n, 0, 8);
    const QRegularExpression heading(QString("^Step %1\\.").arg(n));
    for (QTextBlock block = view_->document()->begin(); block.isValid(); block = block.next())
        if (heading.match(block.text()).hasMatch()) {
            QTextCursor cursor(block);
            view_->moveCursor(QTextCursor::End);
            view_->setTextCursor(cursor);
            view_->ensureCursorVisible();
            break;
        }
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
