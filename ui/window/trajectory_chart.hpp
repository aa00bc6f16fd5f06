#pragma once
// A Qt Charts plot of a trajectory against simulation time with a cursor at the
// playback time: the energies (E_kin green, E_pot blue, E purple, and W, the work of
// friction and torques, red when there is any; a ghost run's E dashed), the joints
// (q_i solid, q̇_i dashed), or any curves over the run given with their unit (a picked
// entry b₁₁(t), a joint's torque parts). Series are replaced once per trajectory, decimated to about
// two points per pixel column, fixed axis ranges, no animations (Qt Charts 6.4's
// append is quadratic). Exports PNG, SVG and CSV (with units).
#include <QChartView>
#include <QString>

#include "core/simulation/trajectory.hpp"

class QLineSeries;
class QValueAxis;

namespace ll::ui {

class TrajectoryChart : public QChartView {
    Q_OBJECT
public:
    enum class Kind { Energy, Joints, Curves };
    explicit TrajectoryChart(Kind kind, QWidget* parent = nullptr);

    void setTrajectory(const Trajectory& trajectory);
    // Kind Curves: the curves to draw over times t, the y axis titled `axisTitle`.
    struct Curve {
        QString name;
        QColor color;
        Qt::PenStyle style = Qt::SolidLine;
        std::vector<double> values;  // one per time
    };
    void setCurves(const std::vector<double>& t, std::vector<Curve> curves, const QString& axisTitle);
    void setGhost(const Trajectory* ghost, const QString& label);  // null: none
    void setCursorTime(double t);
    void clear();
    // Presentation mode: axis labels, titles and legend `scale` times their size, curves
    // as many times as wide (1 = the desktop's). Qt Charts does not follow the
    // application font, so the window's bigger font alone leaves the plots small.
    void setScale(double scale);
    // The legend in Latin Modern (names with dots: B q̈, C q̇).
    void setTextbookFont();
    double scale() const { return scale_; }

    // Points drawn in the curves (not the cursor): a test's "there are curves".
    int curvePoints() const;

    // Writes the plot; throws std::runtime_error naming the file.
    void exportImage(const QString& path);  // .png or .svg
    void exportCsv(const QString& path);

signals:
    // The user clicked or dragged in the plot at time t (to scrub the playback).
    void timePicked(double t);

protected:
    void mousePressEvent(QMouseEvent* e) override;
    void resizeEvent(QResizeEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;

private:
    QLineSeries* addSeries(const QString& name, const QColor& color, Qt::PenStyle style);
    struct Shown {
        QString name;
        QColor color;
        Qt::PenStyle style;
        QList<QPointF> points;
    };
    void showCurves(const std::vector<Shown>& curves);
    void fitAxes();
    // As many ticks as the plot area has room for: a label's width apart on the time
    // axis, two label heights apart on the value axis (no overlapping labels at the
    // window's default size, in presentation mode or in a small dock).
    void fitTicks();

    Kind kind_;
    Trajectory trajectory_, ghost_;
    std::vector<double> times_;  // Kind Curves: the times and curves shown
    std::vector<Curve> curves_;
    bool hasGhost_ = false;
    QString ghostLabel_;  // the ghost run's integrator, named in the legend
    QValueAxis *axisX_, *axisY_;
    QLineSeries* cursor_;
    double yMin_ = 0, yMax_ = 1;
    double dataLo_ = 0, dataHi_ = 1;  // the value range before rounding to nice numbers
    double scale_ = 1.0;
    QFont baseLabels_, baseTitle_, baseLegend_;  // the fonts at scale 1
};

}  // namespace ll::ui
