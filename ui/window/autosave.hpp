#pragma once
// The window's unsaved work kept safe (ui/document/crash_recovery.hpp): its recovery copy
// written every 5 s while there are unsaved edits and removed on save or discard, and,
// after a crash, every copy left behind offered back: this scene's as an undoable restore
// on top of the file as it is, other scenes' apart (open in a new window, discard, or
// keep for later), never in place of the scene asked for.
#include <vector>

#include <QObject>
#include <QString>
#include <QStringList>
#include <QTimer>

#include "ui/document/crash_recovery.hpp"

class QMainWindow;

namespace ll::ui {

class SceneFiles;

class Autosave : public QObject {
    Q_OBJECT
public:
    Autosave(SceneDocument& document, QMainWindow& window);

    // The scene file as opened or saved now (its bytes' hash: a later change on disk is told).
    void setOriginal(const QString& path);
    // Each file `files` opens or saves: the copy of the scene before discarded (asked about
    // in maybeSave), the new file its original.
    void follow(SceneFiles& files);
    void write();
    void discard();
    QString ownFile() const { return recovery_.ownFile(); }
    // Copies left by windows that crashed (named in *damaged: those set aside as cut short).
    std::vector<RecoveryCopy> leftBehind(QStringList* damaged = nullptr) const;
    // Whether `copy` holds edits of the scene this window has open.
    bool isOwnScene(const RecoveryCopy& copy) const;
    // The question asked about a copy: the file named, when it was saved, a warning first
    // when the file changed on disk since, and what the edits change.
    QString question(const RecoveryCopy& copy) const;
    // Restores a copy of this window's scene as an undoable, unsaved edit on top of the
    // file as it is; the copy is replaced by this window's own.
    bool restore(const RecoveryCopy& copy);
    // Asks about every copy left by a crash.
    void offer();

private:
    SceneDocument& doc_;
    QMainWindow& window_;
    QTimer timer_;
    CrashRecovery recovery_{CrashRecovery::defaultDirectory()};
    QString originalHash_;  // of the scene file's bytes as opened or last saved
};

}  // namespace ll::ui
