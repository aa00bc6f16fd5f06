#include "ui/window/scene_files.hpp"

#include <QDir>
#include <QEventLoop>
#include <QFileDialog>
#include <QFileInfo>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>

#include "ui/window/relabel.hpp"
#include "ui/document/app_language.hpp"
#include "ui/document/live_derivation.hpp"
#include "ui/document/scene_document.hpp"
#include "ui/window/example_gallery.hpp"
#include "core/io/scene_file.hpp"
#include "core/io/urdf_import.hpp"

namespace ll::ui {

namespace {

constexpr int kMaxRecent = 8;

QString sceneFilter() { return SceneFiles::tr("LagrangeLab scenes (*.lagrange *.json);;All files (*)"); }

}  // namespace

SceneFiles::SceneFiles(SceneDocument& document, LiveDerivation& derivation, QMainWindow& window)
    : doc_(document), derive_(derivation), window_(window) {}

void SceneFiles::addOpenEntries(QMenu* file) {
    Relabel& relabel = *new Relabel(&window_);
    QAction* open = file->addAction(QString(), QKeySequence::Open, this, &SceneFiles::open);
    QAction* import = file->addAction(QString(), this, [this] {
        if (!maybeSave()) return;
        const QString path =
            QFileDialog::getOpenFileName(&window_, tr("Import a robot from URDF"), QFileInfo(doc_.path()).absolutePath(), tr("URDF robots (*.urdf);;All files (*)"));
        if (!path.isEmpty()) importUrdf(path);
    });
    QMenu* examples = file->addMenu(QString());
    QAction* gallery = examples->addAction(QString(), this, [this] {
        auto* dialog = new ExampleGallery(&window_);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        connect(dialog, &ExampleGallery::chosen, this, &SceneFiles::openAsked);
        dialog->open();
    });
    recentMenu_ = file->addMenu(QString());
    relabel([open, import, examples, gallery, recent = recentMenu_] {
        open->setText(tr("&Open…"));
        import->setText(tr("&Import URDF…"));
        examples->setTitle(tr("Examples"));
        gallery->setText(tr("Gallery…"));
        recent->setTitle(tr("Recent files"));
    });
    examples->addSeparator();
    for (const QString& name : QDir(":/examples").entryList({"*.json"}, QDir::Files, QDir::Name))
        examples->addAction(name, this, [this, name] { openAsked(":/examples/" + name); });
    rebuildRecentMenu();
}

void SceneFiles::addSaveEntries(QMenu* file) {
    QAction* save = file->addAction(QString(), QKeySequence::Save, this, &SceneFiles::save);
    QAction* saveAs = file->addAction(QString(), QKeySequence::SaveAs, this, &SceneFiles::saveAs);
    (*new Relabel(&window_))([save, saveAs] {
        save->setText(tr("&Save"));
        saveAs->setText(tr("Save &as…"));
    });
}

void SceneFiles::openAsked(const QString& path) {
    if (maybeSave()) openFile(path);
}

bool SceneFiles::openFile(const QString& path, QStringList* errors, bool quiet) {
    const bool loaded = load(
        QFileInfo(path).fileName(), [&](std::function<void(bool, const QStringList&)> done) { doc_.loadFileInBackground(path, std::move(done)); },
        errors, quiet);
    if (!loaded) return false;
    if (!path.startsWith(":/")) addRecent(QFileInfo(path).absoluteFilePath());
    emit opened(path);
    return true;
}

bool SceneFiles::importUrdf(const QString& path, QStringList* errors, bool quiet) {
    std::string text;
    try {
        const UrdfImport imported = importUrdfFile(path.toStdString(), {});
        text = serializeScene(imported.scene);
    } catch (const std::exception& e) {
        const QStringList found{shownError(e, windowLanguage())};
        if (errors) *errors = found;
        if (!quiet) QMessageBox::warning(&window_, tr("Cannot import %1").arg(QFileInfo(path).fileName()), found.join('\n'));
        return false;
    }
    const bool loaded = load(
        QFileInfo(path).fileName(),
        [&](std::function<void(bool, const QStringList&)> done) { doc_.loadUnsavedInBackground(std::move(text), path, std::move(done)); },
        errors, quiet);
    if (loaded) emit opened(QString());
    return loaded;
}

bool SceneFiles::openText(const std::string& text, const QString& name, QStringList* errors, bool quiet) {
    const bool loaded = load(
        name, [&](std::function<void(bool, const QStringList&)> done) { doc_.loadUnsavedInBackground(text, name, std::move(done)); },
        errors, quiet);
    if (loaded) emit opened(QString());
    return loaded;
}

bool SceneFiles::load(const QString& name, const std::function<void(std::function<void(bool, const QStringList&)>)>& start, QStringList* errors,
                      bool quiet) {
    if (opening_) {
        if (errors) *errors = QStringList{tr("%1: another file is being opened").arg(name)};
        return false;
    }
    derive_.cancel();  // loading checks the scene under the GiNaC lock
    // The check runs on the document's worker; the window keeps drawing meanwhile.
    opening_ = true;
    window_.statusBar()->showMessage(tr("Opening %1…").arg(name));
    QEventLoop loop;
    bool done = false, loaded = false;
    QStringList found;
    start([&](bool ok, const QStringList& lines) {
        done = true;
        loaded = ok;
        found = lines;
        loop.quit();
    });
    if (!done) loop.exec(QEventLoop::ExcludeUserInputEvents);
    opening_ = false;
    window_.statusBar()->clearMessage();
    if (loaded) return true;
    derive_.resume();
    if (errors) *errors = found;
    if (!quiet) {
        QMessageBox box(QMessageBox::Warning, tr("Cannot open %1").arg(name), tr("The scene has errors; the open scene is kept."),
                        QMessageBox::Ok, &window_);
        box.setDetailedText(found.join('\n'));
        box.setInformativeText(found.mid(0, 6).join('\n'));
        box.exec();
    }
    window_.statusBar()->showMessage(tr("%1: %n error(s), nothing changed", "", found.size()).arg(name), 8000);
    return false;
}

bool SceneFiles::saveTo(const QString& path, QString* error) {
    try {
        doc_.saveFile(path);
    } catch (const std::exception& e) {
        if (error) *error = shownError(e, windowLanguage());
        return false;
    }
    addRecent(QFileInfo(path).absoluteFilePath());
    emit saved(path);
    return true;
}

void SceneFiles::open() {
    if (!maybeSave()) return;
    const QString path = QFileDialog::getOpenFileName(&window_, tr("Open scene"), QFileInfo(doc_.path()).absolutePath(), sceneFilter());
    if (!path.isEmpty()) openFile(path);
}

bool SceneFiles::save() {
    if (doc_.path().isEmpty()) return saveAs();
    QString error;
    if (!saveTo(doc_.path(), &error)) {
        QMessageBox::critical(&window_, tr("Save"), error);
        return false;
    }
    return true;
}

bool SceneFiles::saveAs() {
    const QString path = QFileDialog::getSaveFileName(&window_, tr("Save scene as"), doc_.path(), sceneFilter());
    if (path.isEmpty()) return false;
    QString error;
    if (!saveTo(path, &error)) {
        QMessageBox::critical(&window_, tr("Save"), error);
        return false;
    }
    return true;
}

bool SceneFiles::maybeSave() {
    if (!doc_.isModified() || !askBeforeClosing_) return true;
    const auto answer = QMessageBox::warning(&window_, tr("Unsaved changes"), tr("The scene has unsaved changes. Save them?"),
                                             QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save) return save();
    return answer == QMessageBox::Discard;
}

void SceneFiles::addRecent(const QString& path) {
    QSettings settings("LagrangeLab", "LagrangeLab");
    QStringList recent = settings.value("recent").toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    settings.setValue("recent", recent.mid(0, kMaxRecent));
    rebuildRecentMenu();
}

void SceneFiles::rebuildRecentMenu() {
    if (!recentMenu_) return;
    recentMenu_->clear();
    QSettings settings("LagrangeLab", "LagrangeLab");
    for (const QString& path : settings.value("recent").toStringList())
        recentMenu_->addAction(path, this, [this, path] { openAsked(path); });
    recentMenu_->setEnabled(!recentMenu_->isEmpty());
}

}  // namespace ll::ui
