#pragma once
// File → Export: the window's screenshot, the plot shown, the derivation on screen, the
// animation, a video for slides and the lab report. The menu's entries ask for the path
// and call the *To functions, which tests and scripts call directly. The derivation, the
// animation and the report are written on a worker from copies of what is on screen
// (nothing shared with the window); `finished` says when.
#include <atomic>
#include <functional>

#include <QImage>
#include <QObject>
#include <QSize>
#include <QString>

#include "ui/window/window_parts.hpp"

class QMenu;

namespace ll::ui {

class SceneDocument;

// The window as the screen shows it, the GL view included (QWidget::grab() misses its overlay).
QImage screenshotOf(QWidget& window);

class ExportActions : public QObject {
    Q_OBJECT
public:
    ExportActions(const SceneDocument& document, const OnScreen& shown, const WindowParts& parts);

    // The entries of File → Export.
    void addTo(QMenu* menu);

    // Plot: the tab shown (energy or joints) as .png, .svg or .csv, at once. Derivation:
    // .pdf (typeset, as `derive --format pdf`), .svg or .png pages, .tex or .txt, from the
    // derivation on screen. Animation: .mp4, .webm, .gif, a .png still or a folder of
    // frames by the offscreen renderer (`render`), with a progress dialog and Cancel when
    // `withDialog`; `slide`, a valid size, renders the composite slide
    // (ui/paint/composite_frame.hpp) with the derivation step shown (8 when the window
    // shows the pose results). Lab report (ui/document/lab_report.hpp): the bundle into
    // folder `dir`. All return false with the reason when they cannot start; those on a
    // worker emit finished(path, error) when done.
    bool plotTo(const QString& path, QString* error = nullptr);
    bool derivationTo(const QString& path, QString* error = nullptr);
    bool animationTo(const QString& path, QString* error = nullptr, double duration = -1, bool withDialog = true, QSize slide = {});
    bool labReportTo(const QString& dir, QString* error = nullptr, bool withDialog = true);

signals:
    // An export on a worker is done: `error` empty when `path` was written.
    void finished(const QString& path, const QString& error);

private:
    using Work = std::function<void(const std::function<void(double)>& progress, const std::atomic<bool>* cancel)>;
    void onWorker(const QString& target, const QString& label, bool withDialog, Work work);
    void report(const QString& path, const QString& error, bool dialog);
    void askScreenshot();
    void askPlot();
    void askDerivation();
    void askAnimation(QSize slide);
    void askLabReport();

    const SceneDocument& doc_;
    const OnScreen& shown_;
    const WindowParts& parts_;
};

}  // namespace ll::ui
