#include "ui/window/exercise_mode.hpp"

#include <algorithm>

#include <QTabWidget>

#include "core/present/message_text.hpp"
#include "core/visual/visual_emphasis.hpp"
#include "ui/document/app_language.hpp"
#include "ui/document/entry_selection.hpp"
#include "ui/document/scene_document.hpp"
#include "ui/window/entry_linking.hpp"
#include "ui/window/exercise_panel.hpp"
#include "ui/window/model_editor.hpp"

namespace ll::ui {

namespace {

// An entry id as one token of a JSON pointer ("dL/dx_dot" → "dL~1dx_dot").
std::string pointerToken(const QString& entry) {
    std::string out;
    for (char c : entry.toStdString()) out += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
    return out;
}

QString words(const Message& m) { return QString::fromStdString(present::messageText(m, windowLanguage())); }

}  // namespace

ExerciseMode::ExerciseMode(SceneDocument& document, const EntrySelection& selection, EntryLinking& linking, OnScreen& shown,
                           const WindowParts& parts, ExercisePanel& panel)
    : doc_(document), selection_(selection), linking_(linking), shown_(shown), parts_(parts), panel_(panel) {
    connect(&doc_, &SceneDocument::changed, this, &ExerciseMode::documentChanged);
    connect(&doc_, &SceneDocument::exerciseChanged, this, &ExerciseMode::documentChanged);
    connect(&doc_, &SceneDocument::exerciseChanged, parts_.editor, &ModelEditor::refreshJson);  // the JSON tab shows the answers too
    connect(&checking_, &AnswerChecking::keyReady, this, &ExerciseMode::keyReady);
    connect(&checking_, &AnswerChecking::keyFailed, this, [this](const QString& why) {
        panel_.setStatus(tr("Answers cannot be checked for this scene: %1").arg(why));
        placesKnown_ = true;  // nothing to hide by: the derivation is shown as it is
        emit hiddenChanged();
    });
    connect(&checking_, &AnswerChecking::checked, this, &ExerciseMode::checked);
    connect(&panel_, &ExercisePanel::answerTyped, this,
            [this](const QString& entry, const QString& answer) { checking_.check(entry, answer, revealing_.count(entry) > 0); });
    connect(&panel_, &ExercisePanel::answerFinished, this, &ExerciseMode::commit);
    connect(&panel_, &ExercisePanel::checkRequested, this, [this](const QString& entry, const QString& answer) {
        judging_[entry] = answer;
        checking_.check(entry, answer, revealing_.count(entry) > 0);
    });
    connect(&panel_, &ExercisePanel::revealRequested, this, [this](const QString& entry) {
        revealing_.insert(entry);
        checking_.check(entry, panel_.answer(entry), true);
    });
    connect(&panel_, &ExercisePanel::addStepRequested, this, [this](int step) {
        if (checking_.key()) ask(checking_.practiceEntries(step), tr("Practise step %1").arg(step));
    });
    connect(&panel_, &ExercisePanel::addPickedRequested, this, [this] {
        const auto& key = checking_.key();
        if (key && selection_.entry())
            ask(key->entriesOf(selection_.entry()->id), tr("Practise %1").arg(QString::fromStdString(selection_.entry()->label)));
    });
    connect(&panel_, &ExercisePanel::clearRequested, this, [this] { doc_.setValue("/exercise", nullptr, tr("End the exercise")); });
    connect(&selection_, &EntrySelection::selectionChanged, this, &ExerciseMode::derivationShown);
    // The key is built when the tab is first looked at (the steps it offers need it), or for
    // a scene opened with an exercise.
    connect(parts_.derivationTabs, &QTabWidget::currentChanged, this, [this] {
        if (parts_.derivationTabs->currentWidget() == &panel_ && !checking_.key() && !checking_.building()) buildKey();
    });
}

void ExerciseMode::sceneChanged() {
    if (active() || checking_.key() || checking_.building()) buildKey();
}

void ExerciseMode::buildKey() {
    checking_.setScene(doc_.validScene());
    panel_.setStatus(tr("Making the answer key (the derivation, entry by entry)…"));  // a second for a 6-joint arm
}

void ExerciseMode::documentChanged() {
    const Exercise exercise = doc_.exercise();
    if (exercise.entries != asked_) {
        const bool was = active();
        asked_ = exercise.entries;
        if (!active()) {
            places_.clear();
            placesKnown_ = false;
            judging_.clear();
            revealing_.clear();
            light({});
        } else if (!was && !checking_.key()) {
            if (!checking_.building()) buildKey();
        }
        if (checking_.key()) keyReady();  // the places of the entries asked now
        else showEntries();
        if (!active()) emit hiddenChanged();
    }
    for (const auto& [entry, answer] : exercise.answers) panel_.setAnswer(QString::fromStdString(entry), QString::fromStdString(answer));
}

void ExerciseMode::keyReady() {
    const auto& key = checking_.key();
    places_.clear();
    for (const std::string& id : asked_)
        if (present::EntryPlace p = key->place(id); p.step >= 0) places_.push_back(p);
    placesKnown_ = true;
    showEntries();
    derivationShown();
    panel_.setStatus(QString());
    emit hiddenChanged();
    // the answers saved with the scene judged again (the progress per step, for this scene's numbers)
    for (const auto& [entry, answer] : doc_.exercise().answers) {
        const QString e = QString::fromStdString(entry), a = QString::fromStdString(answer);
        if (std::find(asked_.begin(), asked_.end(), entry) == asked_.end() || a.trimmed().isEmpty()) continue;
        judging_[e] = a;
        checking_.check(e, a);
    }
}

void ExerciseMode::derivationShown() {
    const auto& key = checking_.key();
    std::vector<ExercisePanel::Step> choices;
    const present::DisplayDocument* shown = shown_.derived ? shown_.derived->display.get() : nullptr;
    if (key && shown)
        for (const present::DisplayStep& step : shown->steps)
            if (!checking_.practiceEntries(step.number).empty())
                choices.push_back({step.number, tr("Step %1: %2").arg(step.number).arg(words(step.title)), {}});
    panel_.setChoices(choices, key && selection_.entry());
    if (active()) showEntries();  // the steps' titles in the derivation's language
}

void ExerciseMode::showEntries() {
    const auto& key = checking_.key();
    const present::DisplayDocument* shown = shown_.derived ? shown_.derived->display.get() : nullptr;
    std::vector<ExercisePanel::Step> steps;
    for (const std::string& id : asked_) {
        const int number = key ? key->place(id).step : 0;
        auto step = std::find_if(steps.begin(), steps.end(), [&](const ExercisePanel::Step& s) { return s.number == number; });
        if (step == steps.end()) {
            QString title = tr("Entries not in this derivation");
            if (number >= 0 && !key) title = tr("The answer key is being made…");
            else if (const present::DisplayStep* s = shown ? shown->step(number) : nullptr)
                title = tr("Step %1: %2").arg(number).arg(words(s->title));
            else if (number >= 0) title = tr("Step %1").arg(number);
            steps.push_back({number, title, {}});
            step = steps.end() - 1;
        }
        step->entries << QString::fromStdString(id);
    }
    std::stable_sort(steps.begin(), steps.end(),
                     [](const auto& a, const auto& b) { return (a.number < 0 ? 99 : a.number) < (b.number < 0 ? 99 : b.number); });
    panel_.setEntries(steps);
    for (const auto& [entry, answer] : doc_.exercise().answers)  // the new fields; a field being typed in keeps its text
        if (panel_.answer(QString::fromStdString(entry)).isEmpty())
            panel_.setAnswer(QString::fromStdString(entry), QString::fromStdString(answer));
}

void ExerciseMode::checked(const QString& entry, const QString& answer, const AnswerCheck& c) {
    if (answer != panel_.answer(entry)) return;  // typed on since: a newer check follows
    panel_.showReading(entry, c.verdict == AnswerVerdict::Unreadable ? QString() : QString::fromStdString(c.readAs));
    if (revealing_.count(entry) && !c.rightAnswer.empty()) panel_.showRight(entry, QString::fromStdString(c.rightAnswer));
    const auto judged = judging_.find(entry);
    if (judged == judging_.end() || judged->second != answer) return;
    judging_.erase(judged);
    QStringList lines;
    if (c.verdict == AnswerVerdict::Unreadable) lines << words(c.problem);
    if (c.writtenDifferently) lines << words(Message(MessageId::AnswerWrittenDifferently));
    if (c.withValues) lines << words(Message(MessageId::AnswerWithValues));
    for (const Message& hint : c.hints) lines << words(hint);
    const ExercisePanel::Mark mark = c.verdict == AnswerVerdict::Right   ? ExercisePanel::Mark::Right
                                     : c.verdict == AnswerVerdict::Wrong ? ExercisePanel::Mark::Wrong
                                                                         : ExercisePanel::Mark::Unreadable;
    panel_.showVerdict(entry, mark, lines);
    light(c.verdict == AnswerVerdict::Wrong ? c.links : std::vector<int>{});
}

void ExerciseMode::commit(const QString& entry, const QString& answer) {
    if (QString::fromStdString(doc_.exercise().answer(entry.toStdString())) == answer) return;
    doc_.setValue("/exercise/answers/" + pointerToken(entry), answer.toStdString(), tr("Answer %1").arg(entry));
}

void ExerciseMode::ask(const std::vector<std::string>& entries, const QString& description) {
    std::vector<std::string> asked = asked_;
    for (const std::string& id : entries)
        if (std::find(asked.begin(), asked.end(), id) == asked.end()) asked.push_back(id);
    if (asked != asked_) doc_.setValue("/exercise/entries", asked, description);
    parts_.derivationTabs->setCurrentWidget(&panel_);
}

void ExerciseMode::light(const std::vector<int>& links) {
    if (shown_.litLinks == links) return;
    shown_.litLinks = links;
    linking_.showLit();
}

}  // namespace ll::ui
