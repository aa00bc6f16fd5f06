#pragma once
// The scene's file: open (checked on a worker while the window keeps drawing; a scene
// with errors is refused and the open one kept), save and save as (atomic, PATH.bak),
// the recent files, the examples, and a question before unsaved work is closed.
#include <functional>
#include <string>

#include <QObject>
#include <QString>
#include <QStringList>

class QMainWindow;
class QMenu;

namespace ll::ui {

class LiveDerivation;
class SceneDocument;

class SceneFiles : public QObject {
    Q_OBJECT
public:
    SceneFiles(SceneDocument& document, LiveDerivation& derivation, QMainWindow& window);

    // Opens `path` (a file or a ":/examples/…" resource); waits for its check in a local
    // event loop. On failure the errors are shown (a dialog unless `quiet`), returned in
    // *errors, and the open document is kept.
    bool openFile(const QString& path, QStringList* errors = nullptr, bool quiet = false);
    // File → Import URDF…: the robot in `path` as a new scene (lagrangelab import's), unsaved
    // (Save asks for its name); refused as openFile refuses, the open scene kept.
    bool importUrdf(const QString& path, QStringList* errors = nullptr, bool quiet = false);
    // A scene's text (a view's or lesson's embedded scene) as the document, unsaved, named
    // `name`; refused as openFile refuses.
    bool openText(const std::string& text, const QString& name, QStringList* errors = nullptr, bool quiet = false);
    bool saveTo(const QString& path, QString* error = nullptr);
    // Asks what to do with unsaved edits: true when the caller may go on.
    bool maybeSave();
    void setAskBeforeClosing(bool on) { askBeforeClosing_ = on; }
    bool asksBeforeClosing() const { return askBeforeClosing_; }

    // File menu entries: Open, Examples, Recent files, Save, Save as.
    void addOpenEntries(QMenu* file);
    void addSaveEntries(QMenu* file);
    void open();
    bool save();

signals:
    // A scene was opened or saved at `path`.
    void opened(const QString& path);
    void saved(const QString& path);

private:
    bool saveAs();
    void addRecent(const QString& path);
    void rebuildRecentMenu();
    void openAsked(const QString& path);  // after maybeSave
    // Starts the document's check with `start(done)` and waits for it in a local event loop;
    // on errors shows them (unless `quiet`) and keeps the open scene.
    bool load(const QString& name, const std::function<void(std::function<void(bool, const QStringList&)>)>& start, QStringList* errors,
              bool quiet);

    SceneDocument& doc_;
    LiveDerivation& derive_;
    QMainWindow& window_;
    QMenu* recentMenu_ = nullptr;
    bool askBeforeClosing_ = true;
    bool opening_ = false;  // a file is being checked (openFile waits for its worker)
};

}  // namespace ll::ui
