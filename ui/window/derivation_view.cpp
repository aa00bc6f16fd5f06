#include "ui/window/derivation_view.hpp"

#include "ui/window/derivation_canvas.hpp"
#include "ui/window/relabel.hpp"

#include <QBoxLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "core/model/cancellation.hpp"
#include "core/pipeline/display_derivation.hpp"
#include "core/pipeline/pose_results.hpp"
#include "core/present/message_text.hpp"
#include "core/present/step_formula_text.hpp"

namespace ll::ui {

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
    canvas_->picked = [this](int item, int row, int col) { emit entryPicked(step_ == poseStepNumber ? -1 : shownIndex_, item, row, col); };
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
double DerivationView::scrollFraction() const {
    const QScrollBar* bar = scroll_->verticalScrollBar();
    return bar->maximum() > bar->minimum() ? double(bar->value() - bar->minimum()) / (bar->maximum() - bar->minimum()) : 0.0;
}

void DerivationView::setScrollFraction(double fraction) {
    QScrollBar* bar = scroll_->verticalScrollBar();
    bar->setValue(bar->minimum() + static_cast<int>(std::lround(std::clamp(fraction, 0.0, 1.0) * (bar->maximum() - bar->minimum()))));
}

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
    if (pose_) rows.emplace_back(poseStepNumber, tr("Results at the teach pose"));
    // A typed Lagrangian goes from step 0 to 6: its list says why, at step 0.
    const bool typed = document_ && !document_->robot;
    const auto rowText = [&](int n, const QString& title) {
        const QString row = tr("Step %1: %2").arg(n).arg(title);
        return typed && n == 0 ? tr("%1 (steps 1–5 are a robot's)").arg(row) : row;
    };
    std::vector<int> numbers;
    for (const auto& [n, title] : rows) numbers.push_back(n);
    bool retitled = false;  // the same steps in another language
    for (int i = 0; i < steps_->count() && i < static_cast<int>(rows.size()); ++i)
        retitled = retitled ||
                   steps_->item(i)->text() != rowText(rows[static_cast<std::size_t>(i)].first, rows[static_cast<std::size_t>(i)].second);
    if (numbers != listed_ || retitled || steps_->count() != static_cast<int>(rows.size())) {
        const QSignalBlocker quiet(steps_);
        steps_->clear();
        for (const auto& [n, title] : rows) steps_->addItem(rowText(n, title));
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
        derivations_.deliver(request, [this, document, error] { accept(document, error); });
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
    if (deriving_) status_->setText(tr("Deriving…"));
    else if (!document_ && error_.isEmpty()) status_->setText(tr("No scene"));
    else if (!error_.isEmpty() || !document_) status_->setText(tr("Error: %1").arg(error_));
    else if (document_->form.empty()) status_->setText(QString::fromStdString(document_->systemName));
    else
        status_->setText(tr("%1 (%2 form)")
                             .arg(QString::fromStdString(document_->systemName),
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
    const present::DisplayStep* shown = step_ == poseStepNumber ? pose_.get() : nullptr;
    if (shown && document_) {  // the teach pose's sentence in the document's language
        poseWritten_ = *shown;
        poseWritten_.formulaText = present::formulaText(shown->general, {document_->language, document_->notation, document_->robot});
        shown = &poseWritten_;
    }
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
    if (!pose_ && had && step_ == poseStepNumber) showStep(listed_.size() > 1 ? listed_[listed_.size() - 2] : listed_.front());
    relist();
    if (step_ == poseStepNumber || had != (pose_ != nullptr)) refresh();
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
        if (m.step == shownIndex_ && (shownIndex_ >= 0 || step_ == poseStepNumber)) here.push_back({m.item, m.row, m.col, m.colour});
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
