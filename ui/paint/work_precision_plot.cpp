#include "ui/paint/work_precision_plot.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>

#include <QFontMetricsF>
#include <QPainterPath>

#include "ui/paint/plot_axes.hpp"

namespace ll::ui {
namespace {

struct Series {
    QString name;
    QColor color;
    std::vector<QPointF> points;  // (cpu, value), in setting order
};

void paintPanel(QPainter& p, const QRectF& box, const QString& title, const QString& yLabel, const std::vector<Series>& series, DecadeRange xr,
                DecadeRange yr, double floorValue, const QString& floorLabel, std::vector<QRectF>* tickLabels) {
    const QFontMetricsF fm(p.font());
    const QRectF plot = box.adjusted(fm.horizontalAdvance("10−00") + 34, fm.height() * 1.8, -12, -fm.height() * 2.8);
    const auto X = [&](double v) { return plot.left() + (std::log10(v) - xr.lo) / (xr.hi - xr.lo) * plot.width(); };
    const auto Y = [&](double v) { return plot.bottom() - (std::log10(v) - yr.lo) / (yr.hi - yr.lo) * plot.height(); };

    p.setPen(Qt::black);
    QFont bold = p.font();
    bold.setBold(true);
    p.setFont(bold);
    p.drawText(QRectF(box.left(), box.top(), box.width(), fm.height() * 1.5), Qt::AlignCenter, title);
    p.setFont(QFont(p.font().family(), p.font().pointSize()));

    // grid: decades solid light, 2..9 faint; a decade's label where it fits (every 2nd or
    // 3rd decade on a small panel), so no two labels overlap
    const int xStep = labelStep(plot.width(), xr.hi - xr.lo, fm.horizontalAdvance("10−00") + fm.averageCharWidth());
    const int yStep = labelStep(plot.height(), yr.hi - yr.lo, fm.height() * 1.1);
    std::vector<QRectF> xLabels;
    for (int d = xr.lo; d <= xr.hi; ++d) {
        for (int m = 1; m <= 9 && !(d == xr.hi && m > 1); ++m) {
            const double x = X(m * std::pow(10.0, d));
            p.setPen(QPen(m == 1 ? QColor(200, 200, 200) : QColor(235, 235, 235), 1));
            p.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
        }
        p.setPen(Qt::black);
        if ((d - xr.lo) % xStep != 0) continue;
        const QRectF r = drawPowerOfTen(p, QPointF(X(std::pow(10.0, d)), plot.bottom() + fm.height() * 1.1), d, 0);
        xLabels.push_back(r);
        if (tickLabels) tickLabels->push_back(r);
    }
    for (int d = yr.lo; d <= yr.hi; ++d) {
        for (int m = 1; m <= 9 && !(d == yr.hi && m > 1); ++m) {
            const double y = Y(m * std::pow(10.0, d));
            p.setPen(QPen(m == 1 ? QColor(200, 200, 200) : QColor(240, 240, 240), 1));
            p.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
        }
        p.setPen(Qt::black);
        if ((d - yr.lo) % yStep != 0) continue;
        const QPointF at(plot.left() - 6, Y(std::pow(10.0, d)) + fm.ascent() / 2 - 1);
        // the lowest decade's label can meet the time axis's first one in the corner
        const QRectF box = drawPowerOfTen(p, at, d, 1, false);
        if (std::any_of(xLabels.begin(), xLabels.end(), [&](const QRectF& x) { return x.intersects(box); })) continue;
        const QRectF r = drawPowerOfTen(p, at, d, 1);
        if (tickLabels) tickLabels->push_back(r);
    }
    p.setPen(QPen(Qt::black, 1.2));
    p.setBrush(Qt::NoBrush);
    p.drawRect(plot);
    p.drawText(QRectF(plot.left(), plot.bottom() + fm.height() * 1.5, plot.width(), fm.height() * 1.2), Qt::AlignCenter,
               "CPU time [s] (median of repeats)");
    p.save();
    p.translate(box.left() + fm.height() * 0.2, plot.center().y());
    p.rotate(-90);
    p.drawText(QRectF(-plot.height() / 2, 0, plot.height(), fm.height() * 1.2), Qt::AlignCenter, yLabel);
    p.restore();

    p.save();
    p.setClipRect(plot.adjusted(-4, -4, 4, 4));
    if (floorValue > 0 && std::isfinite(floorValue)) {
        p.setPen(QPen(QColor(90, 90, 90), 1.2, Qt::DashLine));
        const double y = Y(std::max(floorValue, std::pow(10.0, yr.lo)));
        p.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
        p.drawText(QPointF(plot.left() + 6, y - 4), floorLabel);
    }
    p.setRenderHint(QPainter::Antialiasing, true);
    for (const Series& s : series) {
        if (s.points.empty()) continue;
        QPainterPath path;
        for (size_t k = 0; k < s.points.size(); ++k) {
            const QPointF q(X(s.points[k].x()), Y(s.points[k].y()));
            if (k == 0) path.moveTo(q);
            else path.lineTo(q);
        }
        p.setPen(QPen(s.color, 2.0));
        p.setBrush(Qt::NoBrush);
        p.drawPath(path);
        p.setBrush(s.color);
        for (const QPointF& v : s.points) p.drawEllipse(QPointF(X(v.x()), Y(v.y())), 3.5, 3.5);
    }
    p.restore();
}

}  // namespace

void paintWorkPrecision(QPainter& p, const QRectF& area, const WorkPrecisionResult& result, std::vector<QRectF>* tickLabels) {
    p.save();
    p.fillRect(area, Qt::white);
    QFont font = p.font();
    font.setPointSizeF(std::max(7.0, area.height() / 62.0));
    p.setFont(font);
    const QFontMetricsF fm(font);

    // Values below this are drawn on the bottom edge (an exact match has no logarithm).
    constexpr double kTiny = 1e-17;
    std::vector<Series> errors, drifts;
    std::vector<double> xs, ys1, ys2;
    int failed = 0;
    std::map<std::string, size_t> index;
    for (const WorkPrecisionPoint& pt : result.points) {
        if (!index.count(pt.integrator)) {
            index[pt.integrator] = errors.size();
            const QColor color = plotColor(errors.size());
            errors.push_back({QString::fromStdString(pt.integrator), color, {}});
            drifts.push_back({QString::fromStdString(pt.integrator), color, {}});
        }
        if (!pt.completed || !(pt.cpuSeconds > 0)) {
            failed += pt.completed ? 0 : 1;
            continue;
        }
        const size_t i = index[pt.integrator];
        const double e = std::max(pt.finalError, kTiny), d = std::max(pt.maxRelEnergyDrift, kTiny);
        errors[i].points.emplace_back(pt.cpuSeconds, e);
        drifts[i].points.emplace_back(pt.cpuSeconds, d);
        xs.push_back(pt.cpuSeconds);
        ys1.push_back(e);
        ys2.push_back(d);
    }
    ys1.push_back(std::max(result.reference.estimatedError, kTiny));
    const DecadeRange xr = decadesOf(xs), yr1 = decadesOf(ys1), yr2 = decadesOf(ys2);

    const double titleH = fm.height() * 3.2, legendW = fm.horizontalAdvance("symplectic_euler (failed)") + 40;
    p.setPen(Qt::black);
    QFont titleFont = font;
    titleFont.setPointSizeF(font.pointSizeF() * 1.25);
    titleFont.setBold(true);
    p.setFont(titleFont);
    p.drawText(QRectF(area.left(), area.top() + 4, area.width(), fm.height() * 1.6), Qt::AlignCenter,
               QString("What accuracy costs: %1, %2 s simulated").arg(QString::fromStdString(result.scene)).arg(result.duration));
    p.setFont(font);
    p.drawText(QRectF(area.left(), area.top() + fm.height() * 1.7, area.width(), fm.height() * 1.3), Qt::AlignCenter,
               QString("reference: %1 at tol %2 (its own error ≈ %3); error = max |x − x_ref| / (1 + |x_ref|) over q and "
                       "dq/dt at t = T; adaptive methods at tol, fixed-step ones at dt")
                   .arg(QString::fromStdString(result.reference.integrator))
                   .arg(result.reference.tolerance, 0, 'g', 2)
                   .arg(result.reference.estimatedError, 0, 'g', 2));

    const double panelW = (area.width() - legendW) / 2;
    const QRectF left(area.left(), area.top() + titleH, panelW, area.height() - titleH);
    const QRectF right(area.left() + panelW, area.top() + titleH, panelW, area.height() - titleH);
    paintPanel(p, left, "final-state error vs CPU time", "final-state error", errors, xr, yr1, result.reference.estimatedError,
               "reference error estimate", tickLabels);
    paintPanel(p, right, "energy drift vs CPU time", "max relative energy drift |E − E0 − W| / E", drifts, xr, yr2, 0, {}, tickLabels);

    // legend
    const double lx = area.left() + 2 * panelW + 10;
    double ly = area.top() + titleH + fm.height() * 2;
    p.setPen(Qt::black);
    p.drawText(QPointF(lx, ly), "integrator");
    ly += fm.height() * 0.6;
    for (const Series& s : errors) {
        ly += fm.height() * 1.3;
        p.setPen(QPen(s.color, 2.5));
        p.drawLine(QPointF(lx, ly - fm.ascent() / 3), QPointF(lx + 26, ly - fm.ascent() / 3));
        p.setBrush(s.color);
        p.drawEllipse(QPointF(lx + 13, ly - fm.ascent() / 3), 3.5, 3.5);
        p.setPen(Qt::black);
        p.drawText(QPointF(lx + 32, ly), s.name + (s.points.empty() ? " (failed)" : ""));
    }
    if (failed > 0) {
        ly += fm.height() * 2;
        p.setPen(QColor(150, 0, 0));
        p.drawText(QRectF(lx, ly - fm.ascent(), legendW - 12, fm.height() * 4), Qt::TextWordWrap,
                   QString("%1 run%2 stopped early (not drawn; see the table)").arg(failed).arg(failed == 1 ? "" : "s"));
    }
    p.restore();
}

bool saveWorkPrecisionPlot(const WorkPrecisionResult& result, const QString& path, QString* error, QSize size) {
    return savePaintedPlot(
        path, size, "Work–precision: " + QString::fromStdString(result.scene),
        [&](QPainter& painter, const QRectF& area) { paintWorkPrecision(painter, area, result); }, error);
}

}  // namespace ll::ui
