#include "ui/window/export_actions.hpp"

#include <algorithm>

#include <QApplication>
#include <QBuffer>
#include <QFileDialog>
#include <QFileInfo>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QPointer>
#include <QProgressDialog>
#include <QScreen>
#include <QStatusBar>
#include <QTabWidget>
#include <QThreadPool>
#include <QWindow>

#include "core/io/atomic_file.hpp"
#include "core/pipeline/pose_results.hpp"
#include "ui/window/relabel.hpp"
#include "ui/document/animation_export.hpp"
#include "ui/document/app_language.hpp"
#include "ui/document/lab_report.hpp"
#include "ui/document/scene_document.hpp"
#include "ui/paint/derivation_pages.hpp"
#include "ui/window/derivation_view.hpp"
#include "ui/window/playback_bar.hpp"
#include "ui/window/scene_view.hpp"
#include "ui/window/trajectory_chart.hpp"

namespace ll::ui {

QImage screenshotOf(QWidget& window) {
    if (QScreen* screen = window.windowHandle() ? window.windowHandle()->screen() : QGuiApplication::primaryScreen()) {
        const QPixmap pixmap = screen->grabWindow(window.winId());
        if (!pixmap.isNull()) return pixmap.toImage();
    }
    return window.grab().toImage();
}

ExportActions::ExportActions(const SceneDocument& document, const OnScreen& shown, const WindowParts& parts)
    : doc_(document), shown_(shown), parts_(parts) {}

void ExportActions::addTo(QMenu* menu) {
    Relabel& relabel = *new Relabel(parts_.window);
    QAction* screenshot = menu->addAction(QString(), this, &ExportActions::askScreenshot);
    QAction* plot = menu->addAction(QString(), this, &ExportActions::askPlot);
    QAction* derivation = menu->addAction(QString(), this, &ExportActions::askDerivation);
    QAction* animation = menu->addAction(QString(), this, [this] { askAnimation({}); });
    relabel([screenshot, plot, derivation, animation] {
        screenshot->setText(tr("Screenshot (PNG)…"));
        plot->setText(tr("Plot (PNG, SVG or CSV)…"));
        derivation->setText(tr("Derivation (PDF, SVG, PNG, LaTeX or text)…"));
        animation->setText(tr("Animation (MP4, WebM, GIF)…"));
    });
    // One video for a slide: the 3D view, the derivation step shown and the energy plot.
    for (const QSize size : {QSize(1280, 720), QSize(1920, 1080)}) {
        QAction* slide = menu->addAction(QString(), this, [this, size] { askAnimation(size); });
        relabel([slide, size] {
            slide->setText(tr("Video for slides, %1×%2 (3D view, equation, energy)…").arg(size.width()).arg(size.height()));
        });
    }
    QAction* report = menu->addAction(QString(), this, &ExportActions::askLabReport);
    relabel([report] { report->setText(tr("Lab report (PDF, CSV, SVG plots, scene, video) into a folder…")); });
}

// ---------------------------------------------------------------- asking for the path

void ExportActions::askScreenshot() {
    QMainWindow* window = parts_.window;
    const QString path = QFileDialog::getSaveFileName(window, tr("Save screenshot"), "screenshot.png", tr("PNG images (*.png)"));
    if (path.isEmpty()) return;
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    screenshotOf(*window).save(&buffer, "PNG");
    try {
        saveFileAtomically(path.toStdString(), bytes.toStdString(), Backup::None);
    } catch (const std::exception& e) {
        QMessageBox::critical(window, tr("Screenshot"), shownError(e, windowLanguage()));
    }
}

void ExportActions::askPlot() {
    const QString path =
        QFileDialog::getSaveFileName(parts_.window, tr("Export plot"), "energy.png", tr("PNG (*.png);;SVG (*.svg);;CSV (*.csv)"));
    QString error;
    if (!path.isEmpty() && !plotTo(path, &error)) QMessageBox::critical(parts_.window, tr("Export plot"), error);
}

void ExportActions::askDerivation() {
    QString filter;
    QString path = QFileDialog::getSaveFileName(
        parts_.window, tr("Export derivation"), "derivation.pdf",
        tr("PDF, typeset (*.pdf);;SVG, typeset, a file per page (*.svg);;PNG, typeset, a file per page (*.png);;LaTeX (*.tex);;Text (*.txt)"),
        &filter);
    // A name typed without an extension takes the chosen filter's (*.svg → .svg).
    if (const qsizetype star = filter.indexOf("(*."); !path.isEmpty() && QFileInfo(path).suffix().isEmpty() && star >= 0)
        path += filter.mid(star + 2, filter.indexOf(')', star) - star - 2);
    QString error;
    if (!path.isEmpty() && !derivationTo(path, &error)) QMessageBox::critical(parts_.window, tr("Export derivation"), error);
}

void ExportActions::askAnimation(QSize slide) {
    const QString title = slide.isValid() ? tr("Export video for slides") : tr("Export animation");
    const QString path = QFileDialog::getSaveFileName(parts_.window, title, slide.isValid() ? "slide.mp4" : "animation.mp4",
                                                      tr("MP4 (*.mp4);;WebM (*.webm);;GIF (*.gif);;PNG still (*.png)"));
    QString error;
    if (!path.isEmpty() && !animationTo(path, &error, -1, true, slide)) QMessageBox::critical(parts_.window, title, error);
}

void ExportActions::askLabReport() {
    const QString dir = QFileDialog::getExistingDirectory(parts_.window, tr("Lab report: choose or make a folder"));
    QString error;
    if (!dir.isEmpty() && !labReportTo(dir, &error)) QMessageBox::critical(parts_.window, tr("Lab report"), error);
}

// ---------------------------------------------------------------- writing

bool ExportActions::plotTo(const QString& path, QString* error) {
    TrajectoryChart* chart = parts_.plotTabs->currentWidget() == parts_.joints ? parts_.joints : parts_.energy;
    try {
        if (!shown_.result) throw std::runtime_error(tr("nothing to export: the simulation has not finished").toStdString());
        if (path.endsWith(".csv", Qt::CaseInsensitive)) chart->exportCsv(path);
        else chart->exportImage(path);
    } catch (const std::exception& e) {
        if (error) *error = shownError(e, windowLanguage());
        return false;
    }
    parts_.window->statusBar()->showMessage(tr("Plot written to %1").arg(path), 8000);
    return true;
}

// An export finished on a worker: said in the status bar, an error in a dialog unless the
// caller is a test or script (no dialog asked).
void ExportActions::report(const QString& path, const QString& error, bool dialog) {
    QStatusBar* bar = parts_.window->statusBar();
    if (error.isEmpty()) bar->showMessage(tr("Written: %1").arg(path), 10000);
    else if (error != "cancelled" && dialog) QMessageBox::critical(parts_.window, tr("Export"), error);
    else bar->showMessage(tr("Export of %1 stopped: %2").arg(path, error), 10000);
}

bool ExportActions::derivationTo(const QString& path, QString* error) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix != "pdf" && suffix != "svg" && suffix != "png" && suffix != "tex" && suffix != "txt") {
        if (error) *error = tr("%1: expected a .pdf, .svg, .png, .tex or .txt file").arg(path);
        return false;
    }
    if (!shown_.derived || !shown_.derived->display) {
        if (error) *error = tr("nothing to export: the derivation has not finished");
        return false;
    }
    // The document on screen: no new derivation. Typeset pages as `derive --format
    // pdf|svg|png` (ui/paint/derivation_pages: SVG and PNG write page k beside FILE as
    // STEM-k.EXT), LaTeX and text rendered from the same display trees.
    auto display = shown_.derived->display;
    QThreadPool::globalInstance()->start([display, path, suffix, self = QPointer<ExportActions>(this), language = windowLanguage()] {
        QString failure, shown = path;  // shown: what the status bar names
        try {
            if (suffix == "pdf") {
                std::string reason;
                if (!writePdf(*display, path, reason)) failure = QString::fromStdString(reason);
            } else if (suffix == "svg" || suffix == "png") {
                std::string reason;
                const DerivationPages pages = paginate(*display);
                std::vector<QString> written;
                if (!(suffix == "svg" ? writeSvg(pages, path, reason, &written) : writePng(pages, path, reason, &written)))
                    failure = QString::fromStdString(reason);
                else if (written.size() > 1)
                    shown =
                        tr("%1 … %2 (%n pages)", nullptr, static_cast<int>(written.size())).arg(path, QFileInfo(written.back()).fileName());
                if (failure.isEmpty())
                    if (const auto older = pagesBeyond(path, static_cast<int>(written.size())); !older.empty())
                        shown += (older.size() == 1 ? tr("; 1 page file of an earlier, longer export remains beside it, not deleted: %1")
                                                    : tr("; %n page files of an earlier, longer export remain beside it, not deleted: %1",
                                                         nullptr, static_cast<int>(older.size())))
                                     .arg(fileNameRange(older));
            } else {
                const auto format = suffix == "tex" ? present::DocumentFormat::Latex : present::DocumentFormat::Text;
                saveFileAtomically(path.toStdString(), present::renderDocument(*display, format), Backup::None);
            }
        } catch (const std::exception& e) {
            failure = shownError(e, language);
        }
        QMetaObject::invokeMethod(
            qApp,
            [self, path, shown, failure] {
                if (!self) return;
                self->report(shown, failure, self->parts_.window->isVisible());
                emit self->finished(path, failure);
            },
            Qt::QueuedConnection);
    });
    parts_.window->statusBar()->showMessage(tr("Writing %1…").arg(path));
    return true;
}

bool ExportActions::animationTo(const QString& path, QString* error, double duration, bool withDialog, QSize slide) {
    if (!shown_.result || !shown_.sampler) {
        if (error) *error = tr("nothing to export: the simulation has not finished");
        return false;
    }
    ExportSettings settings;
    try {
        settings.out = path.toStdString();
        settings.kind = outputKindFor(settings.out);
        const std::string problem = outputProblem(settings.out, settings.kind);
        if (!problem.empty()) throw std::runtime_error(problem);
    } catch (const std::exception& e) {
        if (error) *error = QString::fromUtf8(e.what());
        return false;
    }
    const TrajectorySampler& sampler = *shown_.sampler;
    const double whole = sampler.endTime() - sampler.startTime();
    settings.duration = duration > 0 ? std::min(duration, whole) : whole;
    settings.speed = parts_.playback->speed();
    settings.at = parts_.playback->time();
    settings.trail = parts_.view->showTrail();
    settings.frames = parts_.view->showFrames();
    settings.frameLabels = parts_.view->showLabels();
    if (slide.isValid()) {
        settings.composite = true;
        settings.width = slide.width(), settings.height = slide.height();
        if (shown_.derived && shown_.derived->display) {
            const present::DisplayDocument& document = *shown_.derived->display;
            const int step = parts_.typeset->step();
            const present::DisplayStep* shownStep = document.step(step == poseStepNumber ? symbolic::lastModelStep : step);
            if (!shownStep && !document.steps.empty()) shownStep = &document.steps.back();
            if (shownStep) settings.step = std::make_shared<const present::DisplayStep>(*shownStep);
            settings.language = document.language;
        }
    }
    auto result = shown_.result;
    onWorker(path, tr("Rendering %1…").arg(QFileInfo(path).fileName()), withDialog,
             [result, settings](const std::function<void(double)>& progress, const std::atomic<bool>* cancel) {
                 exportAnimation(*result->scene, result->simulation.trajectory, settings, progress, cancel);
             });
    return true;
}

bool ExportActions::labReportTo(const QString& dir, QString* error, bool withDialog) {
    if (!shown_.result || !shown_.derived || !shown_.derived->display) {
        if (error) *error = tr("nothing to report yet: the simulation or the derivation has not finished");
        return false;
    }
    LabReportInput input;  // copies: the worker shares nothing with the window
    input.scene = *shown_.result->scene;
    input.simulation = shown_.result->simulation;
    input.display = shown_.derived->display;
    input.sceneText = doc_.text();
    input.sceneFileName = doc_.path().isEmpty() ? "scene.json" : QFileInfo(doc_.path()).fileName().toStdString();
    onWorker(dir, tr("Writing the lab report into %1…").arg(dir), withDialog,
             [input = std::move(input), dir](const std::function<void(double)>& progress, const std::atomic<bool>* cancel) {
                 writeLabReport(input, dir.toStdString(), progress, cancel);
             });
    return true;
}

// `work` on a worker, with a progress dialog and Cancel when `withDialog`; then the status
// bar (or a message box) says how it went and finished(target, error) is emitted.
void ExportActions::onWorker(const QString& target, const QString& label, bool withDialog, Work work) {
    QPointer<QProgressDialog> dialog;
    auto cancel = std::make_shared<std::atomic<bool>>(false);
    if (withDialog) {
        dialog = new QProgressDialog(label, tr("Cancel"), 0, 1000, parts_.window);
        dialog->setWindowModality(Qt::WindowModal);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->setMinimumDuration(0);
        connect(dialog, &QProgressDialog::canceled, this, [cancel] { cancel->store(true); });
        dialog->show();
    }
    QThreadPool::globalInstance()->start(
        [self = QPointer<ExportActions>(this), dialog, cancel, work = std::move(work), target, withDialog, language = windowLanguage()] {
            QString failure;
            try {
                work(
                    [dialog](double f) {
                        QMetaObject::invokeMethod(
                            qApp,
                            [dialog, f] {
                                if (dialog) dialog->setValue(static_cast<int>(f * 1000));
                            },
                            Qt::QueuedConnection);
                    },
                    cancel.get());
            } catch (const std::exception& e) {
                failure = shownError(e, language);
            }
            QMetaObject::invokeMethod(
                qApp,
                [self, dialog, target, failure, withDialog] {
                    if (dialog) dialog->close();
                    if (!self) return;
                    self->report(target, failure, withDialog);
                    emit self->finished(target, failure);
                },
                Qt::QueuedConnection);
        });
}

}  // namespace ll::ui
