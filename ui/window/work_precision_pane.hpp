#pragma once
// The work–precision tab: runs `lagrangelab accuracy`'s sweep (core/pipeline
// runWorkPrecision) on the current scene in a worker thread with a progress bar and a
// cancel button, and paints the result with the same painter as the CLI's plot.
#include <atomic>
#include <memory>
#include <optional>

#include <QWidget>

#include "core/model/scene.hpp"
#include "core/simulation/work_precision.hpp"
#include "ui/document/newest_wins.hpp"
#include "ui/document/work_pool.hpp"

class QLabel;
class QProgressBar;
class QPushButton;

namespace ll::ui {

class WorkPrecisionPane : public QWidget {
    Q_OBJECT
public:
    explicit WorkPrecisionPane(QWidget* parent = nullptr);
    ~WorkPrecisionPane() override;

    void setScene(const Scene& scene);
    void run();
    void cancel();
    bool hasResult() const { return result_.has_value(); }
    bool saveImage(const QString& path, QString* error);
    // The plot in a window of its own (Open large…), 90 % × 80 % of the screen; null
    // without a result.
    QWidget* openLarge();

signals:
    void finished();

protected:
    void paintEvent(QPaintEvent* e) override;

private:
    Scene scene_;
    std::optional<WorkPrecisionResult> result_;
    QPushButton *run_, *cancel_, *large_;
    QProgressBar* progress_;
    QLabel* label_;
    WorkPool pool_;
    bool introShown_ = true;  // the label still says what the sweep does (no run started)
    NewestWins sweep_;        // Run again or Cancel: the older sweep stops, its results are dropped
};

}  // namespace ll::ui
