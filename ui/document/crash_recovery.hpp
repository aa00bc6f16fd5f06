#pragma once
// Crash recovery: every window autosaves its unsaved edits to a copy of its own in the
// recovery folder (named after the scene's path and the window's process, written
// atomically, removed on save or discard), so two windows on the same scene never
// overwrite each other's copy. After a crash the copies whose process is gone are
// offered: the one of the scene being opened as a restore on top of that file (naming the
// file, listing what changed, saying so first when the file changed on disk since), the
// others apart, never in place of the scene that was asked for. A copy cut short or empty
// (a power loss while writing it) is never half-loaded: it is set aside as `.damaged`
// with a message.
#include <QDateTime>
#include <QString>
#include <QStringList>

#include <vector>

#include "ui/document/scene_document.hpp"

namespace ll::ui {

struct RecoveryCopy {
    QString file;          // the copy in the recovery folder
    QString original;      // the scene file it belongs to; empty for a scene never saved
    QString originalHash;  // SHA-256 of the original's bytes when its edits began ("" if none)
    SceneJson scene;       // the edited scene
    QDateTime written;     // when it was autosaved
};

class CrashRecovery {
public:
    // `directory`: where the copies live ($LAGRANGELAB_RECOVERY_DIR, else the app's data folder).
    explicit CrashRecovery(QString directory);
    ~CrashRecovery();  // keeps the copy: a window that goes away without a save or discard crashed
    CrashRecovery(const CrashRecovery&) = delete;
    CrashRecovery& operator=(const CrashRecovery&) = delete;
    static QString defaultDirectory();

    // This window's copy of `scene`, the edits of `original` (whose bytes hashed to
    // `originalHash` when they began). Throws std::runtime_error naming the path on failure.
    void write(const QString& original, const QString& originalHash, const SceneJson& scene);
    // Removes this window's copy (a save, a discard, a clean exit).
    void discard();
    QString ownFile() const { return own_; }

    // Copies left by windows whose process has ended, newest first. A copy that does not
    // read as a whole recovery copy is renamed to FILE.damaged and named in *damaged.
    std::vector<RecoveryCopy> leftBehind(QStringList* damaged) const;

    // Whether the original file's bytes differ from those the edits were made on.
    static bool originalChanged(const RecoveryCopy& copy);
    // What the copy changes against `before` (the file as it is), one line each as field
    // paths read ("robot.joints[0].a: 1 → 1.2"), at most `most` (then "… and N more").
    static QStringList changes(const SceneJson& before, const SceneJson& after, int most = 8);
    static QString hashOfFile(const QString& path);
    static void remove(const RecoveryCopy& copy);

private:
    QString directory_, own_;
};

}  // namespace ll::ui
