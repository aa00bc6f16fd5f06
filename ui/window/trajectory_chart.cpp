#include "ui/window/trajectory_chart.hpp"

#include "ui/window/relabel.hpp"

#include "ui/paint/round_step.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <QBuffer>
#include <QChart>
#include <QLegend>
#include <QTimer>
#include <QLegendMarker>
#include <QLineSeries>
#include <QMouseEvent>
#include <QPainter>
#include <QSvgGenerator>
#include <QValueAxis>

#include "core/io/atomic_file.hpp"
#include "ui/paint/math_typesetter.hpp"

namespace ll::ui {

namespace {

// At most about `target` points of (t, y(k)): every stride-th sample plus the last.
template <class Y>
QList<QPointF> decimated(const std::vector<double>& t, Y&& y, int target = 1600) {
    QList<QPointF> points;
    const int n = static_cast<int>(t.size());
    if (n == 0) return points;
    const int stride = std::max(1, n / target);
    points.reserve(n / stride + 2);
    for (int k = 0; k < n; k += stride) points.append(QPointF(t[k], y(k)));
    if ((n - 1) % stride != 0) points.append(QPointF(t[n - 1], y(n - 1)));
    return points;
}

bool anyWork(const Trajectory& tr) {
    return std::any_of(tr.work.begin(), tr.work.end(), [](double w) { return std::abs(w) > 1e-12; });
}

const QColor kJointColours[] = {QColor(31, 119, 180),  QColor(255, 127, 14), QColor(44, 160, 44),   QColor(214, 39, 40),
                                QColor(148, 103, 189), QColor(140, 86, 75),  QColor(227, 119, 194), QColor(127, 127, 127)};

}  // namespace

// The chart is given to QChartView's constructor: QChartView(parent) makes a default chart
// of its own, and setChart() would release it to nobody (a leak of a whole QChart per view,
// found by LeakSanitizer in every window test).
TrajectoryChart::TrajectoryChart(Kind kind, QWidget* parent) : QChartView(new QChart, parent), kind_(kind) {
    QChart* chart = this->chart();
    chart->setAnimationOptions(QChart::NoAnimation);
    chart->legend()->setAlignment(Qt::AlignRight);
    chart->setMargins(QMargins(4, 4, 4, 4));
    setRenderHint(QPainter::Antialiasing);
    axisX_ = new QValueAxis;
    axisX_->setLabelFormat("%.4g");  // 1.25 s, not 1.3 (a 5 s run's quarter ticks)
    axisY_ = new QValueAxis;
    chart->addAxis(axisX_, Qt::AlignBottom);
    chart->addAxis(axisY_, Qt::AlignLeft);
    cursor_ = new QLineSeries;
    cursor_->setPen(QPen(QColor(60, 60, 60), 1.2, Qt::SolidLine));
    chart->addSeries(cursor_);
    cursor_->attachAxis(axisX_);
    cursor_->attachAxis(axisY_);
    for (QLegendMarker* m : chart->legend()->markers(cursor_)) m->setVisible(false);
    baseLabels_ = axisX_->labelsFont();
    baseTitle_ = axisX_->titleFont();
    baseLegend_ = chart->legend()->font();
    (*new Relabel(this))([this] {
        axisX_->setTitleText(tr("t [s]"));
        if (kind_ != Kind::Curves) axisY_->setTitleText(kind_ == Kind::Energy ? tr("energy [J]") : tr("q [rad or m], q̇ [rad/s or m/s]"));
        cursor_->setName(tr("t"));
        if (kind_ != Kind::Curves && !trajectory_.t.empty()) setTrajectory(Trajectory(trajectory_));  // the curves' names
    });
}

namespace {
QFont scaled(QFont font, double scale) {
    if (font.pointSizeF() > 0) font.setPointSizeF(font.pointSizeF() * scale);
    else if (font.pixelSize() > 0) font.setPixelSize(static_cast<int>(font.pixelSize() * scale + 0.5));
    return font;
}
}  // namespace

void TrajectoryChart::setScale(double scale) {
    scale_ = scale;
    for (QValueAxis* axis : {axisX_, axisY_}) {
        axis->setLabelsFont(scaled(baseLabels_, scale));
        axis->setTitleFont(scaled(baseTitle_, scale));
    }
    chart()->legend()->setFont(scaled(baseLegend_, scale));
    fitTicks();
    for (QAbstractSeries* a : chart()->series()) {
        auto* s = static_cast<QLineSeries*>(a);
        QPen pen = s->pen();
        pen.setWidthF((s == cursor_ ? 1.2 : 1.8) * scale);
        s->setPen(pen);
    }
}

void TrajectoryChart::setTextbookFont() {
    baseLegend_ = textbookFont(baseLegend_);
    setScale(scale_);
}

QLineSeries* TrajectoryChart::addSeries(const QString& name, const QColor& color, Qt::PenStyle style) {
    auto* s = new QLineSeries;
    s->setName(name);
    s->setPen(QPen(color, 1.8 * scale_, style));
    chart()->addSeries(s);
    s->attachAxis(axisX_);
    s->attachAxis(axisY_);
    return s;
}

void TrajectoryChart::clear() {
    for (QAbstractSeries* s : chart()->series())
        if (s != cursor_) {
            chart()->removeSeries(s);
            delete s;
        }
}

void TrajectoryChart::setTrajectory(const Trajectory& trajectory) {
    trajectory_ = trajectory;
    times_ = trajectory_.t;
    std::vector<Shown> curves;
    const Trajectory& traj = trajectory_;
    if (kind_ == Kind::Energy) {
        curves.push_back({tr("E_kin"), QColor(34, 139, 34), Qt::SolidLine, decimated(traj.t, [&](int k) { return traj.Ekin[k]; })});
        curves.push_back({tr("E_pot"), QColor(30, 90, 200), Qt::SolidLine, decimated(traj.t, [&](int k) { return traj.Epot[k]; })});
        curves.push_back({tr("E"), QColor(128, 0, 160), Qt::SolidLine, decimated(traj.t, [&](int k) { return traj.E[k]; })});
        if (anyWork(traj)) {
            curves.push_back({tr("W"), QColor(200, 30, 30), Qt::SolidLine, decimated(traj.t, [&](int k) { return traj.work[k]; })});
            curves.push_back(
                {tr("E − W"), QColor(230, 120, 0), Qt::DotLine, decimated(traj.t, [&](int k) { return traj.E[k] - traj.work[k]; })});
        }
        if (hasGhost_)
            curves.push_back({tr("E, ghost (%1)").arg(ghostLabel_), QColor(128, 0, 160, 150), Qt::DashLine,
                              decimated(ghost_.t, [&](int k) { return ghost_.E[k]; })});
    } else if (kind_ == Kind::Joints) {
        for (int i = 0; i < traj.n && i < 8; ++i) {
            const QString name = QString::fromStdString(traj.coordinateName(i));
            curves.push_back({name, kJointColours[i], Qt::SolidLine, decimated(traj.t, [&](int k) { return traj.q[k][i]; })});
            curves.push_back({"d" + name + "/dt", kJointColours[i], Qt::DashLine, decimated(traj.t, [&](int k) { return traj.qd[k][i]; })});
        }
    }
    showCurves(curves);
}

void TrajectoryChart::setCurves(const std::vector<double>& t, std::vector<Curve> curves, const QString& axisTitle) {
    times_ = t;
    curves_ = std::move(curves);
    axisY_->setTitleText(axisTitle);
    std::vector<Shown> shown;
    for (const Curve& c : curves_) {
        if (c.values.size() != t.size()) continue;
        shown.push_back({c.name, c.color, c.style, decimated(t, [&](int k) { return c.values[static_cast<std::size_t>(k)]; })});
    }
    showCurves(shown);
}

void TrajectoryChart::showCurves(const std::vector<Shown>& curves) {
    // The same curves as shown (an edit of a value, not of the structure): new points
    // only, which is much cheaper in Qt Charts than new series.
    QList<QLineSeries*> shown;
    for (QAbstractSeries* s : chart()->series())
        if (s != cursor_) shown.append(static_cast<QLineSeries*>(s));
    bool same = shown.size() == static_cast<qsizetype>(curves.size());
    for (qsizetype i = 0; same && i < shown.size(); ++i)
        same = shown[i]->name() == curves[static_cast<std::size_t>(i)].name &&
               shown[i]->pen().color() == curves[static_cast<std::size_t>(i)].color;
    if (!same) {
        clear();
        shown.clear();
        for (const Shown& c : curves) shown.append(addSeries(c.name, c.color, c.style));
    }
    for (qsizetype i = 0; i < shown.size(); ++i) shown[i]->replace(curves[static_cast<std::size_t>(i)].points);
    fitAxes();
}

void TrajectoryChart::setGhost(const Trajectory* ghost, const QString& label) {
    hasGhost_ = ghost != nullptr;
    if (ghost) ghost_ = *ghost;
    ghostLabel_ = label;
    setTrajectory(Trajectory(trajectory_));
}

void TrajectoryChart::fitAxes() {
    double lo = 1e300, hi = -1e300, tEnd = 0;
    for (QAbstractSeries* a : chart()->series()) {
        if (a == cursor_) continue;
        for (const QPointF& p : static_cast<QLineSeries*>(a)->points()) {
            lo = std::min(lo, p.y()), hi = std::max(hi, p.y());
            tEnd = std::max(tEnd, p.x());
        }
    }
    if (lo > hi) lo = 0, hi = 1;
    // A constant (b22 of the 2R) gets room around it, not a range of its rounding.
    const double pad = hi - lo > 1e-9 * std::max(1.0, std::abs(hi)) ? (hi - lo) * 0.05 : 0.05 * std::max(std::abs(hi), 1e-9);
    dataLo_ = lo - pad, dataHi_ = hi + pad;
    // Evenly spread ticks while the range changes: the round interval of the old range
    // would put millions of ticks on a new range a million times longer.
    axisX_->setTickType(QValueAxis::TicksFixed);
    axisX_->setRange(times_.empty() ? 0 : times_.front(), std::max(tEnd, 1e-6));
    fitTicks();
    // The cursor stays at the time shown (new curves for another joint are of the same run).
    setCursorTime(cursor_->count() ? cursor_->at(0).x() : times_.empty() ? 0 : times_.front());
}

void TrajectoryChart::fitTicks() {
    // The legend beside the plot when it takes at most a fifth of the width, below it
    // otherwise (a narrow dock, presentation mode's larger type) if the plot is tall
    // enough to give a row up; the ticks are fitted again to the plot area that leaves.
    {
        const QFontMetricsF legend(chart()->legend()->font());
        double widest = 0;
        for (QAbstractSeries* s : chart()->series())
            if (s != cursor_) widest = std::max(widest, legend.horizontalAdvance(s->name()));
        const Qt::Alignment side = widest + 3 * legend.height() > 0.2 * width() && height() >= 200 ? Qt::AlignBottom : Qt::AlignRight;
        if (chart()->legend()->alignment() != side) {
            chart()->legend()->setAlignment(side);
            QTimer::singleShot(0, this, [this] {
                const double t = cursor_->count() ? cursor_->at(0).x() : 0;
                fitTicks();
                setCursorTime(t);
            });
        }
    }
    QRectF area = chart()->plotArea();
    if (area.width() < 10 || area.height() < 10) area = QRectF(0, 0, width() * 0.8, height() * 0.7);  // not laid out yet
    const QFontMetricsF fm(axisX_->labelsFont());
    double widest = 0;
    for (double v : {axisX_->min(), axisX_->max(), (axisX_->min() + axisX_->max()) / 2 + 0.0125})
        widest = std::max(widest, fm.horizontalAdvance(QString::asprintf("%.4g", v)));
    // Time ticks at round seconds (1, 2 or 5 times a power of ten, or 2.5) from 0, as many
    // as fit a label's width apart: a 5 s run ticks every second, not every 0.8333 s.
    const int fit = std::clamp(static_cast<int>(area.width() / (widest * 2.0 + 8)) + 1, 2, 11);
    const double span = std::max(axisX_->max() - axisX_->min(), 1e-9);
    axisX_->setTickAnchor(0.0);
    axisX_->setTickInterval(roundStep(span / (fit - 1)));
    axisX_->setTickType(QValueAxis::TicksDynamic);
    axisY_->setRange(dataLo_, dataHi_);
    axisY_->setTickCount(std::clamp(static_cast<int>(area.height() / (QFontMetricsF(axisY_->labelsFont()).height() * 2.0)) + 1, 2, 9));
    axisY_->applyNiceNumbers();  // ticks at round values (no "−0.0" for a 10⁻¹⁵ bound)
    yMin_ = axisY_->min(), yMax_ = axisY_->max();
    // Qt Charts repaints only the regions it thinks changed: an axis given other ticks left
    // its old labels on screen beside the new ones (seen going from view to view of a lesson).
    viewport()->update();
}

void TrajectoryChart::resizeEvent(QResizeEvent* e) {
    QChartView::resizeEvent(e);
    const double t = cursor_->count() ? cursor_->at(0).x() : 0;
    fitTicks();
    setCursorTime(t);
}

void TrajectoryChart::setCursorTime(double t) { cursor_->replace(QList<QPointF>{QPointF(t, yMin_), QPointF(t, yMax_)}); }

int TrajectoryChart::curvePoints() const {
    int n = 0;
    for (QAbstractSeries* a : chart()->series())
        if (a != cursor_) n += static_cast<int>(static_cast<QLineSeries*>(a)->count());
    return n;
}

void TrajectoryChart::mousePressEvent(QMouseEvent* e) {
    if (e->button() == Qt::LeftButton) emit timePicked(chart()->mapToValue(e->position()).x());
    QChartView::mousePressEvent(e);
}

void TrajectoryChart::mouseMoveEvent(QMouseEvent* e) {
    if (e->buttons() & Qt::LeftButton) emit timePicked(chart()->mapToValue(e->position()).x());
    QChartView::mouseMoveEvent(e);
}

void TrajectoryChart::exportImage(const QString& path) {
    if (path.endsWith(".svg", Qt::CaseInsensitive)) {
        QByteArray bytes;
        QBuffer buffer(&bytes);
        buffer.open(QIODevice::WriteOnly);
        QSvgGenerator svg;
        svg.setOutputDevice(&buffer);
        svg.setSize(size());
        svg.setViewBox(rect());
        svg.setTitle(chart()->title());
        QPainter painter(&svg);
        render(&painter);
        painter.end();
        saveFileAtomically(path.toStdString(), bytes.toStdString(), Backup::None);
        return;
    }
    const QPixmap pixmap = grab();
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    pixmap.save(&buffer, "PNG");
    saveFileAtomically(path.toStdString(), bytes.toStdString(), Backup::None);
}

void TrajectoryChart::exportCsv(const QString& path) {
    const Trajectory& tr = trajectory_;
    saveFileAtomically(
        path.toStdString(),
        [&](std::ostream& out) {
            out.precision(12);
            if (kind_ == Kind::Curves) {
                out << "t [s]";
                for (const Curve& c : curves_) out << ',' << c.name.toStdString();
                out << '\n';
                for (std::size_t k = 0; k < times_.size(); ++k) {
                    out << times_[k];
                    for (const Curve& c : curves_) out << ',' << (k < c.values.size() ? c.values[k] : 0.0);
                    out << '\n';
                }
            } else if (kind_ == Kind::Energy) {
                out << "t [s],Ekin [J],Epot [J],E [J],W [J]\n";
                for (std::size_t k = 0; k < tr.size(); ++k)
                    out << tr.t[k] << ',' << tr.Ekin[k] << ',' << tr.Epot[k] << ',' << tr.E[k] << ',' << tr.work[k] << '\n';
            } else {
                out << "t [s]";
                for (int i = 0; i < tr.n; ++i) out << ',' << tr.coordinateName(i);
                for (int i = 0; i < tr.n; ++i) out << ",d" << tr.coordinateName(i) << "/dt";
                out << '\n';
                for (std::size_t k = 0; k < tr.size(); ++k) {
                    out << tr.t[k];
                    for (int i = 0; i < tr.n; ++i) out << ',' << tr.q[k][i];
                    for (int i = 0; i < tr.n; ++i) out << ',' << tr.qd[k][i];
                    out << '\n';
                }
            }
        },
        Backup::None);
}

}  // namespace ll::ui
