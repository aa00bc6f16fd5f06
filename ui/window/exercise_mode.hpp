#pragma once
// Exercise mode: the student answers entries of the derivation themselves. The entries
// asked (a step's, or one picked) are hidden in the typeset and text derivation
// (core/present/hidden_answers); the Exercise tab (ExercisePanel) has a field per entry,
// shows what was read while the student types, and on Check marks the answer green or
// red with the hints in place and lights the links a hint names in the 3D view; Reveal
// gives the right answer. The entries and answers are the scene's "exercise" section:
// each answer is an undoable edit, saved with the scene and in its recovery copy, and
// changes nothing to check, simulate or derive (ui/document/scene_document). The answer
// key is built off the GUI thread once the exercise has entries (ui/document/answer_checking).
#include <map>
#include <set>
#include <vector>

#include <QObject>
#include <QString>

#include "core/present/hidden_answers.hpp"
#include "ui/document/answer_checking.hpp"
#include "ui/window/window_parts.hpp"

namespace ll::ui {

class EntryLinking;
class EntrySelection;
class ExercisePanel;
class SceneDocument;

class ExerciseMode : public QObject {
    Q_OBJECT
public:
    ExerciseMode(SceneDocument& document, const EntrySelection& selection, EntryLinking& linking, OnScreen& shown, const WindowParts& parts,
                 ExercisePanel& panel);

    bool active() const { return !asked_.empty(); }
    // Whether a derivation may be shown now: not while an exercise waits for the key that
    // says where its answers stand (they would show for a moment).
    bool holdsDerivation() const { return active() && !placesKnown_; }
    // Where the answers asked stand in the derivation: hidden there.
    const std::vector<present::EntryPlace>& hidden() const { return places_; }
    // A new valid scene: a new key (the exercise's entries stay).
    void sceneChanged();
    // A derivation is shown: the steps a student can practise follow.
    void derivationShown();
    AnswerChecking& checking() { return checking_; }
    // The key is being made or a Check awaits its verdict.
    bool judging() const { return checking_.building() || !judging_.empty(); }

signals:
    // Other entries are hidden: the derivation is to be shown again.
    void hiddenChanged();

private:
    void documentChanged();
    void buildKey();
    void keyReady();
    void checked(const QString& entry, const QString& answer, const AnswerCheck& result);
    void commit(const QString& entry, const QString& answer);
    void ask(const std::vector<std::string>& entries, const QString& description);
    void showEntries();
    void light(const std::vector<int>& links);

    SceneDocument& doc_;
    const EntrySelection& selection_;
    EntryLinking& linking_;
    OnScreen& shown_;
    const WindowParts& parts_;
    ExercisePanel& panel_;
    AnswerChecking checking_;
    std::vector<std::string> asked_;  // the entries asked, as the scene lists them
    std::vector<present::EntryPlace> places_;
    bool placesKnown_ = false;
    std::map<QString, QString> judging_;  // entry → the answer whose Check is awaited
    std::set<QString> revealing_;
};

}  // namespace ll::ui
