#include "ui/window/autosave.hpp"

#include "ui/window/scene_files.hpp"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QLocale>
#include <QMainWindow>
#include <QMessageBox>
#include <QProcess>
#include <QPushButton>
#include <QStatusBar>

#include "core/io/atomic_file.hpp"
#include "ui/document/app_language.hpp"

namespace ll::ui {

Autosave::Autosave(SceneDocument& document, QMainWindow& window) : doc_(document), window_(window) {
    timer_.setInterval(5000);
    connect(&timer_, &QTimer::timeout, this, [this] {
        if (doc_.isModified()) write();
    });
    timer_.start();
}

void Autosave::follow(SceneFiles& files) {
    for (auto signal : {&SceneFiles::opened, &SceneFiles::saved})
        connect(&files, signal, this, [this](const QString& path) {
            discard();
            setOriginal(path);
        });
}

void Autosave::setOriginal(const QString& path) { originalHash_ = CrashRecovery::hashOfFile(path); }

void Autosave::write() {
    const QString original = doc_.path().startsWith(":/") ? QString() : doc_.path();
    try {
        recovery_.write(original, originalHash_, doc_.json());
    } catch (const std::exception& e) {
        window_.statusBar()->showMessage(tr("Autosave failed: %1").arg(shownError(e, windowLanguage())), 8000);
    }
}

void Autosave::discard() { recovery_.discard(); }

std::vector<RecoveryCopy> Autosave::leftBehind(QStringList* damaged) const { return recovery_.leftBehind(damaged); }

bool Autosave::isOwnScene(const RecoveryCopy& copy) const {
    return !copy.original.isEmpty() && !doc_.path().isEmpty() && QFileInfo(copy.original) == QFileInfo(doc_.path());
}

QString Autosave::question(const RecoveryCopy& copy) const {
    const QString name = copy.original.isEmpty()
                             ? tr("a new scene that was never saved")
                             : tr("%1 (in %2)").arg(QFileInfo(copy.original).fileName(), QFileInfo(copy.original).absolutePath());
    QString text = tr("LagrangeLab did not close normally while %1 had unsaved edits (autosaved %2).")
                       .arg(name, QLocale().toString(copy.written.toLocalTime(), QLocale::ShortFormat));
    SceneJson before = SceneJson::object();
    if (!copy.original.isEmpty()) {
        if (!QFileInfo::exists(copy.original)) {
            text += "\n\n" + tr("%1 no longer exists: the recovered scene is all that is left of it.").arg(copy.original);
        } else {
            if (CrashRecovery::originalChanged(copy))
                text += "\n\n" + tr("Warning: %1 has changed on disk since these edits were made. Restoring puts the "
                                    "recovered scene on top of the file as it is now; undo returns to it.")
                                     .arg(copy.original);
            QFile f(copy.original);
            if (f.open(QIODevice::ReadOnly)) try {
                    before = SceneJson::parse(f.readAll().toStdString());
                } catch (const std::exception&) {
                }
        }
    }
    const QStringList changes = CrashRecovery::changes(before, copy.scene);
    if (!changes.isEmpty()) text += "\n\n" + tr("What the edits change:") + "\n  " + changes.join("\n  ");
    return text;
}

bool Autosave::restore(const RecoveryCopy& copy) {
    if (!isOwnScene(copy)) return false;
    // The file as it is, then the recovered JSON as an unsaved, undoable edit on top:
    // saving writes it back to the file.
    doc_.replace(copy.scene, tr("Restore unsaved edits"));
    write();  // this window's own copy first, then the crashed one goes
    CrashRecovery::remove(copy);
    return true;
}

void Autosave::offer() {
    QStringList damaged;
    const std::vector<RecoveryCopy> copies = leftBehind(&damaged);
    for (const QString& line : damaged) window_.statusBar()->showMessage(line, 15000);
    for (const RecoveryCopy& copy : copies) {
        QMessageBox box(QMessageBox::Question, tr("Restore unsaved work?"), question(copy), QMessageBox::NoButton, &window_);
        if (isOwnScene(copy)) {
            QPushButton* restoreButton = box.addButton(tr("Restore the edits"), QMessageBox::AcceptRole);
            QPushButton* discardButton = box.addButton(tr("Discard them"), QMessageBox::DestructiveRole);
            box.addButton(tr("Keep for later"), QMessageBox::RejectRole);
            box.exec();
            if (box.clickedButton() == restoreButton) restore(copy);
            else if (box.clickedButton() == discardButton) CrashRecovery::remove(copy);
            continue;
        }
        // Another scene's edits: never in place of the scene asked for.
        QPushButton* openButton = box.addButton(tr("Open them in a new window"), QMessageBox::AcceptRole);
        QPushButton* discardButton = box.addButton(tr("Discard them"), QMessageBox::DestructiveRole);
        box.addButton(tr("Keep for later"), QMessageBox::RejectRole);
        box.exec();
        if (box.clickedButton() == discardButton) {
            CrashRecovery::remove(copy);
        } else if (box.clickedButton() == openButton) {
            QString scene = copy.original;
            if (scene.isEmpty() || !QFileInfo::exists(scene)) {  // written out first, so nothing is lost
                scene = QFileInfo(copy.file).absolutePath() + "/recovered-" + copy.written.toString("yyyyMMdd-HHmmss") + ".json";
                try {
                    saveFileAtomically(scene.toStdString(), copy.scene.dump(2), Backup::None);
                } catch (const std::exception& e) {
                    QMessageBox::critical(&window_, tr("Restore unsaved work"), shownError(e, windowLanguage()));
                    continue;
                }
                CrashRecovery::remove(copy);
            }
            QProcess::startDetached(QCoreApplication::applicationFilePath(), {scene});
        }
    }
}

}  // namespace ll::ui
