#pragma once
// The scene being edited in the window: the scene file's JSON as the user typed it
// (expressions, degrees and parameter names kept), an undo stack whose every command
// is one edit, and the last valid Scene. After each change the JSON is read by the
// scene loader (parseScene) and checked by the core (checkScene) in a worker thread
// (both take the GiNaC lock, which a running derivation holds: the GUI thread never
// waits for it); the diagnostics name the bad fields with the loader's own paths
// ("robot.joints[2].a"), and only a document without errors replaces the last valid
// scene, so a bad cell never blanks the view. A newer edit makes an older check's
// result void.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <QObject>
#include <QString>
#include <QStringList>
#include <QUndoStack>

#include "ui/document/handover.hpp"
#include "ui/document/newest_wins.hpp"
#include "ui/document/parameter_uses.hpp"
#include "ui/document/scene_json.hpp"
#include "ui/document/work_pool.hpp"

#include "core/model/diagnostics.hpp"
#include "core/model/scene.hpp"

namespace ll::ui {

class SceneDocument : public QObject {
    Q_OBJECT
public:
    explicit SceneDocument(QObject* parent = nullptr);
    ~SceneDocument() override;

    // Replaces the whole document (a new file, not an undoable edit). Returns false and
    // fills `errors` (one line each, "FILE: field: message") when `text` is not a
    // valid scene; the document is then unchanged.
    bool loadText(const std::string& text, const QString& path, QStringList* errors);
    bool loadFile(const QString& path, QStringList* errors);
    // loadFile with the check (parse, checkScene: under the GiNaC lock, which a running
    // derivation may hold) on the document's worker: `done(loaded, errors)` is called on
    // this object's thread when it is over (at once when the file cannot be read).
    void loadFileInBackground(const QString& path, std::function<void(bool, const QStringList&)> done);
    // The same for a scene's text made here (a URDF imported): no file, so the document has
    // no path and counts as unsaved until it is saved. `name` names it in the errors.
    void loadUnsavedInBackground(std::string text, const QString& name, std::function<void(bool, const QStringList&)> done);
    // Writes the JSON atomically, keeping PATH.bak; throws std::runtime_error.
    void saveFile(const QString& path);

    const SceneJson& json() const { return json_; }
    std::string text() const { return json_.dump(2); }
    QString path() const { return path_; }
    void setPath(const QString& path) { path_ = path; }
    QUndoStack* undoStack() { return &undo_; }
    bool isModified() const { return !undo_.isClean(); }

    // The "exercise" section as it stands now (the entries asked, the answers typed); empty
    // when the scene has none or it is not well formed.
    Exercise exercise() const;

    // The value at `pointer` ("/robot/joints/0/a"), null when absent.
    SceneJson value(const std::string& pointer) const;
    // One undoable edit: the value at `pointer` becomes `v` (null removes it). Successive
    // edits with the same non-zero `gesture` (one slider dragged) are one undo entry, from
    // before the first to after the last.
    void setValue(const std::string& pointer, const SceneJson& v, const QString& description, int gesture = 0);
    // The field the newest edit changed, as the loader names it ("robot.joints[1].com[0]"),
    // when it was one value; empty after any other change (a joint added, undo, a load).
    const std::string& lastEditedField() const { return lastEdited_; }
    // The parameters the newest edit took out of its value that other fields still use
    // (a1 typed over with 1.2 in a DH cell, still in a COM's "lc1-a1"); empty after any
    // other change.
    const std::vector<ParameterStillUsed>& stillUsedAfterLastEdit() const { return stillUsed_; }
    // One undoable edit of the whole document (joints added, moved, a block typed anew).
    void replace(const SceneJson& after, const QString& description, int gesture = 0);

    // Whether the newest JSON is still being checked (diagnostics and validScene are then
    // those of an earlier one).
    bool validating() const { return validated_ < checks_.newest(); }
    // Diagnostics of the newest checked JSON (errors and warnings) and of one field.
    const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }
    QString errorAt(const std::string& field) const;
    bool hasErrors() const { return ll::hasErrors(diagnostics_); }
    // The newest document that had no errors (what the views show).
    const Scene& validScene() const { return validScene_; }
    int validRevision() const { return validRevision_; }

    // A cell's text as typed: a string as is, a number in the shortest exact form.
    static QString display(const SceneJson& v);
    // Typed text to JSON: a number when it reads as one, else the string (an expression).
    static SceneJson parseCell(const QString& text);

signals:
    // After every change of the JSON (edit, undo, redo, load).
    void changed();
    // When the check of a change is done (diagnostics() hold it).
    void validated();
    // When the change gave a valid scene (validScene() holds it).
    void validSceneChanged();
    // Instead of all three, when only the "exercise" section changed (an answer typed, an
    // entry asked): the student's work, not the model, so nothing is checked, simulated
    // or derived again; validScene().exercise holds it.
    void exerciseChanged();

private:
    friend class SceneEditCommand;
    void setJson(const SceneJson& json);  // no undo entry; re-validates
    // The checked text becomes the document (a load), or the errors are listed.
    bool adopt(const std::string& text, const QString& path, std::vector<Diagnostic> found, Scene& scene, QStringList* errors);
    // The text checked on the worker, then adopted on this thread: with `name` as its path
    // when it came from that file, else unsaved.
    void checkInBackground(std::string text, const QString& name, bool fromFile, std::function<void(bool, const QStringList&)> done);
    void validate();
    void accept(std::vector<Diagnostic> diagnostics, Scene* scene);

    SceneJson json_;
    QString path_;
    std::string lastEdited_;
    std::vector<ParameterStillUsed> stillUsed_;
    QUndoStack undo_;
    std::vector<Diagnostic> diagnostics_;
    Scene validScene_;
    int validRevision_ = 0;
    NewestWins checks_;  // a check per revision of the JSON: the newest one is applied
    int validated_ = 0;  // the revision whose check was applied last
    WorkPool checker_;
    Handover loaded_;  // a scene read in the background, back to this thread
};

}  // namespace ll::ui
