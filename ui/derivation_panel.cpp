#include "ui/derivation_panel.hpp"

#include <chrono>

#include <QFontDatabase>
#include <QLabel>
#include <QPlainTextEdit>
#include <QRegularExpression>
#include <QScrollBar>
#include <QTextBlock>
#include <QVBoxLayout>

#include "core/model/cancellation.hpp"
#include "core/model/diagnostics.hpp"
#include "core/pipeline/scene_derivation.hpp"

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
    pool_.setMaxThreadCount(1);
}

DerivationPanel::~DerivationPanel() {
    if (cancel_) cancel_->store(true);
    pool_.waitForDone();
}

void DerivationPanel::setScene(const ll::Scene& scene) {
    if (cancel_) cancel_->store(true);
    cancel_ = std::make_shared<std::atomic<bool>>(false);
    const int request = ++requested_;
    status_->setText(tr("Deriving…"));
    pool_.start([self = this, scene, request, cancel = cancel_] {
        const auto begin = std::chrono::steady_clock::now();
        QString text, error;
        try {
            DocumentRequest r;
            r.format = symbolic::DocumentFormat::Text;
            r.cancel = cancel.get();
            text = QString::fromStdString(deriveDocument(scene, r).document);
        } catch (const Cancelled&) {
            // Stopped for a newer scene, or for an edit being checked: the text shown stays.
            QMetaObject::invokeMethod(self, [self, request] {
                if (request != self->requested_) return;
                self->delivered_ = request;
                self->status_->setText(tr("Derivation stopped: the model is being edited"));
            }, Qt::QueuedConnection);
            return;
        } catch (const InputError& e) {
            for (const Diagnostic& d : e.diagnostics()) error += QString::fromStdString(d.field + ": " + d.message + "\n");
        } catch (const std::exception& e) {
            error = QString::fromStdString(e.what());
        }
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
        QMetaObject::invokeMethod(
            self,
            [self, request, text, error, seconds] {
                if (request < self->requested_) return;
                self->delivered_ = request;
                if (!error.isEmpty()) {
                    self->status_->setText(tr("The derivation stopped: %1").arg(error.trimmed()));
                } else {
                    self->status_->setText(tr("Derived in %1 ms").arg(seconds * 1000, 0, 'f', 0));
                    const int bar = self->view_->verticalScrollBar()->value();
                    self->view_->setPlainText(text);
                    self->view_->verticalScrollBar()->setValue(bar);
                    if (self->step_ > 0) self->showStep(self->step_);
                }
                emit self->derived();
            },
            Qt::QueuedConnection);
    });
}

void DerivationPanel::cancel() {
    if (cancel_) cancel_->store(true);
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
