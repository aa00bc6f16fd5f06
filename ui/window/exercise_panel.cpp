#include "ui/window/exercise_panel.hpp"

#include <QComboBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QTimer>
#include <QVBoxLayout>

#include "ui/window/relabel.hpp"

namespace ll::ui {

namespace {

constexpr int kTypingPauseMs = 250;  // "read as" follows the typing after this pause

const char* markColour(ExercisePanel::Mark mark) {
    switch (mark) {
        case ExercisePanel::Mark::Right: return "#1b7f3a";
        case ExercisePanel::Mark::Wrong: return "#c0392b";
        case ExercisePanel::Mark::Unreadable: return "#b9770e";
        case ExercisePanel::Mark::None: break;
    }
    return "";
}

const char* fieldTint(ExercisePanel::Mark mark) {
    switch (mark) {
        case ExercisePanel::Mark::Right: return "QLineEdit { background: #e3f4e8; }";
        case ExercisePanel::Mark::Wrong: return "QLineEdit { background: #fbe4e1; }";
        case ExercisePanel::Mark::Unreadable: return "QLineEdit { background: #fdf2dc; }";
        case ExercisePanel::Mark::None: break;
    }
    return "";
}

}  // namespace

ExercisePanel::ExercisePanel(QWidget* parent) : QWidget(parent) {
    setObjectName("exercise");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    auto* choose = new QHBoxLayout;
    steps_ = new QComboBox(this);
    steps_->setObjectName("exercise-steps");
    addStep_ = new QPushButton(this);
    addPicked_ = new QPushButton(this);
    clear_ = new QPushButton(this);
    addStep_->setObjectName("exercise-add-step");
    addPicked_->setObjectName("exercise-add-picked");
    clear_->setObjectName("exercise-end");
    choose->addWidget(steps_, 1);
    choose->addWidget(addStep_);
    auto* more = new QHBoxLayout;
    more->addWidget(addPicked_);
    more->addStretch(1);
    more->addWidget(clear_);
    layout->addLayout(choose);
    layout->addLayout(more);
    status_ = new QLabel(this);
    status_->setWordWrap(true);
    status_->hide();
    layout->addWidget(status_);
    empty_ = new QLabel(this);
    empty_->setWordWrap(true);
    layout->addWidget(empty_);
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    list_ = new QWidget(scroll);
    listLayout_ = new QVBoxLayout(list_);
    listLayout_->setContentsMargins(0, 0, 0, 0);
    listLayout_->addStretch(1);
    scroll->setWidget(list_);
    layout->addWidget(scroll, 1);

    connect(addStep_, &QPushButton::clicked, this, [this] {
        if (steps_->currentIndex() >= 0) emit addStepRequested(steps_->currentData().toInt());
    });
    connect(addPicked_, &QPushButton::clicked, this, &ExercisePanel::addPickedRequested);
    connect(clear_, &QPushButton::clicked, this, &ExercisePanel::clearRequested);
    (*new Relabel(this))([this] { relabel(); });
    setEntries({});
}

void ExercisePanel::relabel() {
    addStep_->setText(tr("Practise this step"));
    addStep_->setToolTip(tr("Hide the answers of the step chosen in the derivation and answer them here"));
    addPicked_->setText(tr("Practise the picked entry"));
    addPicked_->setToolTip(tr("Hide the entry picked in the derivation, the entry list or the teach panel"));
    clear_->setText(tr("End the exercise"));
    clear_->setToolTip(tr("Show every answer again and remove the answers typed (undoable)"));
    empty_->setText(tr("Choose a step (or pick an entry) to practise: its answers are hidden in the derivation, and you type "
                       "your own here. Check says whether yours is right and, if not, where it goes wrong; the answers are "
                       "saved with the scene."));
    for (const auto& [step, box] : boxes_) updateHeading(step);
    for (auto& [entry, row] : rows_) row.field->setPlaceholderText(tr("your %1 (c2, q1, m2 lc2^2, …)").arg(entry));
}

ExercisePanel::Row& ExercisePanel::addRow(QWidget* box, const QString& entry, int step) {
    auto* grid = static_cast<QGridLayout*>(box->layout());
    const int line = grid->rowCount();
    Row& row = rows_[entry];
    row.step = step;
    auto* name = new QLabel(QString("<b>%1</b> =").arg(entry.toHtmlEscaped()), box);
    row.field = new QLineEdit(box);
    row.field->setObjectName("answer-" + entry);
    row.field->setPlaceholderText(tr("your %1 (c2, q1, m2 lc2^2, …)").arg(entry));
    auto* check = new QPushButton(tr("Check"), box);
    auto* reveal = new QPushButton(tr("Reveal"), box);
    check->setObjectName("check-" + entry);
    reveal->setObjectName("reveal-" + entry);
    row.reading = new QLabel(box);
    row.verdict = new QLabel(box);
    row.right = new QLabel(box);
    for (QLabel* l : {row.reading, row.verdict, row.right}) {
        l->setWordWrap(true);
        l->setTextInteractionFlags(Qt::TextSelectableByMouse);
        l->hide();
    }
    row.reading->setStyleSheet("color: #555;");
    row.pause = new QTimer(box);
    row.pause->setSingleShot(true);
    row.pause->setInterval(kTypingPauseMs);
    grid->addWidget(name, line, 0);
    grid->addWidget(row.field, line, 1);
    grid->addWidget(check, line, 2);
    grid->addWidget(reveal, line, 3);
    grid->addWidget(row.reading, line + 1, 1, 1, 3);
    grid->addWidget(row.verdict, line + 2, 1, 1, 3);
    grid->addWidget(row.right, line + 3, 1, 1, 3);
    QLineEdit* field = row.field;
    connect(field, &QLineEdit::textEdited, row.pause, qOverload<>(&QTimer::start));
    connect(field, &QLineEdit::textEdited, this, [this, entry] {
        Row& r = rows_[entry];
        if (r.mark != Mark::None) showVerdict(entry, Mark::None, {});  // a new answer: not judged yet
    });
    connect(row.pause, &QTimer::timeout, this, [this, entry, field] { emit answerTyped(entry, field->text()); });
    connect(field, &QLineEdit::editingFinished, this, [this, entry, field] { emit answerFinished(entry, field->text()); });
    connect(field, &QLineEdit::returnPressed, this, [this, entry, field] { emit checkRequested(entry, field->text()); });
    connect(check, &QPushButton::clicked, this, [this, entry, field] {
        emit answerFinished(entry, field->text());
        emit checkRequested(entry, field->text());
    });
    connect(reveal, &QPushButton::clicked, this, [this, entry] { emit revealRequested(entry); });
    return row;
}

void ExercisePanel::setEntries(const std::vector<Step>& steps) {
    std::map<QString, int> asked;
    for (const Step& s : steps)
        for (const QString& entry : s.entries) asked[entry] = s.number;
    empty_->setVisible(steps.empty());
    clear_->setEnabled(!steps.empty());
    bool same = asked.size() == rows_.size() && steps.size() == boxes_.size();
    for (const auto& [entry, step] : asked) same = same && rows_.count(entry) && rows_.at(entry).step == step;
    if (same) {  // the same fields (one may be being typed in): new titles only
        for (const Step& s : steps) {
            titles_[s.number] = s.title;
            updateHeading(s.number);
        }
        return;
    }
    std::map<QString, std::pair<QString, Mark>> kept;
    for (const auto& [entry, row] : rows_) kept[entry] = {row.field->text(), row.mark};
    for (const auto& [step, box] : boxes_) delete box;
    boxes_.clear();
    rows_.clear();
    titles_.clear();
    for (const Step& s : steps) {
        auto* box = new QGroupBox(list_);
        auto* grid = new QGridLayout(box);
        grid->setColumnStretch(1, 1);
        boxes_[s.number] = box;
        titles_[s.number] = s.title;
        listLayout_->insertWidget(listLayout_->count() - 1, box);
        for (const QString& entry : s.entries) {
            Row& row = addRow(box, entry, s.number);
            if (auto k = kept.find(entry); k != kept.end()) {
                row.field->setText(k->second.first);
                row.mark = k->second.second;
            }
        }
        updateHeading(s.number);
    }
}

void ExercisePanel::setChoices(const std::vector<Step>& steps, bool entryPicked) {
    // the step chosen before, else the dynamics' (B and E_kin, step 7), where students start
    const int chosen = steps_->count() > 0 ? steps_->currentData().toInt() : 7;
    steps_->clear();
    for (const Step& s : steps) {
        steps_->addItem(s.title, s.number);
        if (s.number == chosen) steps_->setCurrentIndex(steps_->count() - 1);
    }
    addStep_->setEnabled(!steps.empty());
    addPicked_->setEnabled(entryPicked);
}

void ExercisePanel::setAnswer(const QString& entry, const QString& answer) {
    auto it = rows_.find(entry);
    if (it == rows_.end() || it->second.field->text() == answer) return;
    it->second.field->setText(answer);
    showVerdict(entry, Mark::None, {});
}

QString ExercisePanel::answer(const QString& entry) const {
    auto it = rows_.find(entry);
    return it == rows_.end() ? QString() : it->second.field->text();
}

void ExercisePanel::showReading(const QString& entry, const QString& readAs) {
    auto it = rows_.find(entry);
    if (it == rows_.end()) return;
    it->second.reading->setText(readAs.isEmpty() ? QString() : tr("read as: %1").arg(readAs));
    it->second.reading->setVisible(!readAs.isEmpty());
}

void ExercisePanel::showVerdict(const QString& entry, Mark mark, const QStringList& lines) {
    auto it = rows_.find(entry);
    if (it == rows_.end()) return;
    Row& row = it->second;
    row.mark = mark;
    row.field->setStyleSheet(fieldTint(mark));
    QString html;
    if (mark != Mark::None) {
        const QString word = mark == Mark::Right ? tr("Right.") : mark == Mark::Wrong ? tr("Wrong.") : tr("Cannot read it:");
        html = QString("<span style='color:%1'><b>%2</b></span>").arg(markColour(mark), word);
        for (const QString& line : lines) html += "<br>" + line.toHtmlEscaped();
    }
    row.verdict->setText(html);
    row.verdict->setVisible(!html.isEmpty());
    updateHeading(row.step);
}

void ExercisePanel::showRight(const QString& entry, const QString& rightAnswer) {
    auto it = rows_.find(entry);
    if (it == rows_.end()) return;
    it->second.right->setText(tr("The right answer: %1").arg(rightAnswer.toHtmlEscaped()));
    it->second.right->setVisible(!rightAnswer.isEmpty());
}

void ExercisePanel::setStatus(const QString& text) {
    status_->setText(text);
    status_->setVisible(!text.isEmpty());
}

void ExercisePanel::updateHeading(int step) {
    auto box = boxes_.find(step);
    if (box == boxes_.end()) return;
    int asked = 0, right = 0;
    for (const auto& [entry, row] : rows_)
        if (row.step == step) ++asked, right += row.mark == Mark::Right;
    box->second->setTitle(tr("%1 — %2 of %3 right").arg(titles_[step]).arg(right).arg(asked));
}

ExercisePanel::Mark ExercisePanel::mark(const QString& entry) const {
    auto it = rows_.find(entry);
    return it == rows_.end() ? Mark::None : it->second.mark;
}

QString ExercisePanel::verdictText(const QString& entry) const {
    auto it = rows_.find(entry);
    return it == rows_.end() ? QString() : it->second.verdict->text();
}

QString ExercisePanel::stepHeading(int step) const {
    auto box = boxes_.find(step);
    return box == boxes_.end() ? QString() : box->second->title();
}

QStringList ExercisePanel::entries() const {
    QStringList out;
    for (const auto& [entry, row] : rows_) out << entry;
    return out;
}

QString ExercisePanel::revealed(const QString& entry) const {
    auto it = rows_.find(entry);
    return it == rows_.end() || !it->second.right->isVisibleTo(this) ? QString() : it->second.right->text();
}

QLineEdit* ExercisePanel::field(const QString& entry) const {
    auto it = rows_.find(entry);
    return it == rows_.end() ? nullptr : it->second.field;
}

}  // namespace ll::ui
