#include "ui/window/work_precision_pane.hpp"

#include "ui/window/relabel.hpp"

#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QProgressBar>
#include <QPushButton>
#include <QScreen>
#include <QVBoxLayout>

#include "core/model/cancellation.hpp"
#include "core/pipeline/scene_simulation.hpp"
#include "core/present/message_text.hpp"
#include "ui/document/app_language.hpp"
#include "ui/paint/work_precision_plot.hpp"

namespace ll::ui {

WorkPrecisionPane::WorkPrecisionPane(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    auto* row = new QHBoxLayout;
    run_ = new QPushButton(this);
    cancel_ = new QPushButton(this);
    cancel_->setEnabled(false);
    large_ = new QPushButton(this);
    large_->setEnabled(false);
    progress_ = new QProgressBar(this);
    progress_->setRange(0, 1000);
    label_ = new QLabel(this);
    (*new Relabel(this))([this] {
        run_->setText(tr("Run work–precision sweep"));
        cancel_->setText(tr("Cancel"));
        large_->setText(tr("Open large…"));
        large_->setToolTip(tr("The plot in a window of its own, as large as the screen allows"));
        if (introShown_)
            label_->setText(tr("Error and energy drift against CPU time for every integrator (1 repeat, tolerances 1e-3…1e-10)."));
    });
    row->addWidget(run_);
    row->addWidget(cancel_);
    row->addWidget(large_);
    row->addWidget(progress_, 1);
    layout->addLayout(row);
    label_->setWordWrap(true);  // one line would set the plots dock's minimum width (930 px presenting)
    layout->addWidget(label_);
    layout->addStretch(1);
    pool_.setMaxThreadCount(1);
    connect(run_, &QPushButton::clicked, this, &WorkPrecisionPane::run);
    connect(cancel_, &QPushButton::clicked, this, &WorkPrecisionPane::cancel);
    connect(large_, &QPushButton::clicked, this, &WorkPrecisionPane::openLarge);
}

namespace {
// The plot alone, painted at whatever size its window has.
class PlotWindow : public QWidget {
public:
    PlotWindow(WorkPrecisionResult result, QWidget* parent) : QWidget(parent, Qt::Window), result_(std::move(result)) {
        setAttribute(Qt::WA_DeleteOnClose);
    }

protected:
    void paintEvent(QPaintEvent*) override {
        QPainter painter(this);
        paintWorkPrecision(painter, QRectF(rect()), result_);
    }

private:
    WorkPrecisionResult result_;
};
}  // namespace

QWidget* WorkPrecisionPane::openLarge() {
    if (!result_) return nullptr;
    auto* window = new PlotWindow(*result_, this);
    window->setObjectName("work-precision-large");
    window->setWindowTitle(tr("Work–precision: %1").arg(QString::fromStdString(result_->scene)));
    const QRect screen = this->screen() ? this->screen()->availableGeometry() : QRect(0, 0, 1280, 800);
    window->resize(screen.width() * 9 / 10, screen.height() * 8 / 10);
    window->show();
    return window;
}

WorkPrecisionPane::~WorkPrecisionPane() {
    cancel();
    pool_.waitForDone();
}

void WorkPrecisionPane::setScene(const Scene& scene) { scene_ = scene; }

void WorkPrecisionPane::cancel() { sweep_.cancel(); }

void WorkPrecisionPane::run() {
    introShown_ = false;
    const int generation = sweep_.request();
    NewestWins::Flag stop = sweep_.begin();
    run_->setEnabled(false);
    cancel_->setEnabled(true);
    progress_->setValue(0);
    WorkPrecisionSettings settings;
    settings.repeats = 1;
    settings.tolerances = {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10};
    settings.steps = {1e-2, 3e-3, 1e-3};
    settings.duration = std::min(scene_.simulation.duration, 5.0);
    pool_.start([self = this, scene = scene_, settings, generation, stop, language = windowLanguage()] {
        std::optional<WorkPrecisionResult> result;
        QString error;
        try {
            result = ll::runWorkPrecision(
                scene, settings,
                [self, generation, language](double fraction, const Message& what) {
                    self->sweep_.deliver(generation,
                                         [self, fraction, text = QString::fromStdString(present::messageText(what, language))] {
                                             self->progress_->setValue(static_cast<int>(fraction * 1000));
                                             self->label_->setText(text);
                                         });
                },
                stop.get());
            if (stop->load()) result.reset(), error = tr("cancelled");
            else if (result->status == SimulationStatus::Failed)  // the reference failed: no point to plot
                error = QString::fromStdString(present::messageText(result->message, language)), result.reset();
        } catch (const std::exception& e) {
            error = shownError(e, language);
        }
        self->sweep_.deliver(generation, [self, result = std::move(result), error] {
            self->run_->setEnabled(true);
            self->cancel_->setEnabled(false);
            if (result) {
                self->result_ = result;
                self->progress_->setValue(1000);
                self->large_->setEnabled(true);
                self->label_->setText(tr("Done: %n run(s).", nullptr, static_cast<int>(result->points.size())));
            } else {
                self->label_->setText(tr("Stopped: %1").arg(error));
            }
            self->update();
            emit self->finished();
        });
    });
}

void WorkPrecisionPane::paintEvent(QPaintEvent* e) {
    QWidget::paintEvent(e);
    if (!result_) return;
    QPainter painter(this);
    const int top = label_->geometry().bottom() + 6;
    painter.fillRect(QRect(0, top, width(), height() - top), Qt::white);
    paintWorkPrecision(painter, QRectF(0, top, width(), height() - top), *result_);
}

bool WorkPrecisionPane::saveImage(const QString& path, QString* error) {
    if (!result_) {
        if (error) *error = tr("no work–precision result yet: run the sweep first");
        return false;
    }
    return saveWorkPrecisionPlot(*result_, path, error);
}

}  // namespace ll::ui
