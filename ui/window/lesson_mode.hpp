#pragma once
// A lesson in the window (core/io/lesson_file.hpp): the Lesson dock lists its views (drag to
// reorder, double click to go, F2 to rename), with the selected view's note below, and the
// Lesson menu makes one: New, Open…, Save, Save as…, Add the current view (F9), Update it,
// Remove, Rename, Present; every edit can be undone (the Lesson menu's own undo).
//
// Presenting a lesson: Page Down / Page Up (what a clicker sends) and → / ← go to the next and
// previous view; a view that says "derivation.through": [a, b] is stepped through from a to b
// first, and one that says "playback.play": [t₀, t₁] plays (Space) from t₀ and stops at t₁.
// Each view is restored whole (ui/window/view_state.hpp), its camera kept as saved.
// The speaker's notes, the next view's title and where the lecture stands show in a small
// window of their own, on a second screen when there is one (N shows or hides it; on one
// screen it starts hidden, as it would cover the slide). Leaving presentation mode
// restores the view the lecturer was at before presenting the lesson.
//
// A lesson whose views cannot all be read opens with the others and lists the ones it could
// not; a view that no longer fits its scene is shown as far as it can be, with what it could
// not restore listed in the status line.
#include <array>
#include <functional>
#include <optional>

#include <QObject>
#include <QString>

#include "core/io/lesson_file.hpp"
#include "core/io/window_view.hpp"

class QAction;
class QDockWidget;
class QLabel;
class QListWidget;
class QMenu;
class QMenuBar;
class QPlainTextEdit;
class QUndoStack;
class QWidget;

namespace ll::ui {

class MainWindow;
struct WindowParts;

class LessonMode : public QObject {
    Q_OBJECT
public:
    LessonMode(MainWindow& window, const WindowParts& parts);
    ~LessonMode() override;

    void addMenu(QMenuBar* bar);

    // The lesson (scene paths relative to the current directory) and its file ("" unsaved).
    const Lesson& lesson() const { return lesson_; }
    const QString& path() const { return path_; }
    // Opens `path`; false (and `errors`) when it is no lesson. Views it could not read are
    // listed in `unreadable` ("3. intro: why"), and kept.
    bool open(const QString& path, QStringList* errors = nullptr, QStringList* unreadable = nullptr);
    bool saveTo(const QString& path, QString* error = nullptr);
    void newLesson();
    // Whether the lesson's unsaved edits may go (asks: save, discard, cancel); true when none.
    bool maybeSave();
    void addCurrentView();
    void updateCurrentView();
    void removeView(int index);
    void renameView(int index, const QString& name);
    void moveView(int from, int to);
    // The lesson's own undo stack: every edit above (and the notes typed) is one step.
    QUndoStack* undoStack() const { return undo_; }

    // The view shown (−1: none yet) and going to one; next/previous as the keys do.
    int current() const { return current_; }
    void go(int index);
    void next();
    void previous();
    // Presents the lesson from view `index`.
    void present(int index = 0);
    // The speaker's window (created when a lesson is presented).
    QWidget* speakerNotes() const { return notes_; }

signals:
    void viewShown(int index, const QStringList& problems);  // a view is on screen; what of it could not be restored

private:
    // `change` applied to the lesson as one undoable edit called `what`; successive edits
    // with the same `merge` (> 0: the keys typed into one note) are one step.
    void edit(const QString& what, const std::function<void(Lesson&)>& change, int merge = 0);
    void refreshList();
    void showNotes();
    void presentationChanged(bool on);
    void openAsked();
    void saveAsked(bool as);

    MainWindow& window_;
    const WindowParts& parts_;
    Lesson lesson_;
    QUndoStack* undo_ = nullptr;
    QString path_;
    int current_ = -1;
    bool presenting_ = false;        // presentation mode began with the lesson
    WindowView before_;              // the window before the lesson was presented
    QDockWidget* dock_ = nullptr;
    QLabel* title_ = nullptr;
    QListWidget* list_ = nullptr;
    QPlainTextEdit* note_ = nullptr;  // the selected view's note, edited in place
    QWidget* notes_ = nullptr;        // the speaker's window
    QAction* notesKey_ = nullptr;     // N: the speaker's window shown or hidden
    bool notesWanted_ = false;
    std::optional<std::array<double, 2>> stopAt_;
    QMetaObject::Connection pending_;  // the restore go() waits for  // the view's play range: playing stops at its end
    QLabel *notesNow_ = nullptr, *notesText_ = nullptr, *notesNext_ = nullptr;
};

}  // namespace ll::ui
