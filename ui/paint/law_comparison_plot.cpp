#include "ui/paint/law_comparison_plot.hpp"

#include <algorithm>
#include <cmath>

#include <QFontMetricsF>
#include <QPainterPath>

#include "ui/paint/plot_axes.hpp"

namespace ll::ui {
namespace {

// Values below this are drawn on the bottom edge of the logarithmic panel (an exact match
// has no logarithm).
constexpr double kTiny = 1e-15;

struct Panel {
    QString title, yLabel;
    bool logarithmic = false;
    double lo = 0, hi = 1;  // the y range (decades when logarithmic)
    std::vector<double> LawRun::*values = nullptr;
};

void paintPanel(QPainter& p, const QRectF& box, const Panel& panel, const std::vector<LawRun>& runs, double duration) {
    const QFontMetricsF fm(p.font());
    const QRectF plot = box.adjusted(fm.horizontalAdvance("10−00.00") + 30, fm.height() * 1.8, -16, -fm.height() * 2.8);
    const auto X = [&](double t) { return plot.left() + t / duration * plot.width(); };
    const auto Y = [&](double v) {
        const double y = panel.logarithmic ? std::log10(std::max(v, kTiny)) : v;
        return plot.bottom() - (std::clamp(y, panel.lo, panel.hi) - panel.lo) / (panel.hi - panel.lo) * plot.height();
    };
    p.setPen(Qt::black);
    QFont bold = p.font();
    bold.setBold(true);
    p.setFont(bold);
    p.drawText(QRectF(box.left(), box.top(), box.width(), fm.height() * 1.5), Qt::AlignCenter, panel.title);
    bold.setBold(false);
    p.setFont(bold);
    // grid and labels: decades (log) or five steps (linear) up, five steps along t
    if (panel.logarithmic) {
        const int lo = static_cast<int>(panel.lo), hi = static_cast<int>(panel.hi);
        const int step = labelStep(plot.height(), hi - lo, fm.height() * 1.1);
        for (int d = lo; d <= hi; ++d) {
            const double y = Y(std::pow(10.0, d));
            p.setPen(QPen(QColor(215, 215, 215), 1));
            p.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
            p.setPen(Qt::black);
            if ((d - lo) % step == 0) drawPowerOfTen(p, QPointF(plot.left() - 6, y + fm.ascent() / 2 - 1), d, 1);
        }
    } else {  // steps of 1, 2 or 5 times a power of ten, about five of them
        const double raw = (panel.hi - panel.lo) / 5, power = std::pow(10.0, std::floor(std::log10(raw)));
        const double step = power * (raw / power <= 1 ? 1 : raw / power <= 2 ? 2 : raw / power <= 5 ? 5 : 10);
        for (double v = std::ceil(panel.lo / step) * step; v <= panel.hi + 1e-9 * step; v += step) {
            const double y = Y(v);
            p.setPen(QPen(QColor(215, 215, 215), 1));
            p.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
            p.setPen(Qt::black);
            p.drawText(QRectF(box.left(), y - fm.height() / 2, plot.left() - box.left() - 6, fm.height()), Qt::AlignRight | Qt::AlignVCenter,
                       QString::number(v, 'g', 3));
        }
    }
    for (int k = 0; k <= 5; ++k) {
        const double t = duration * k / 5, x = X(t);
        p.setPen(QPen(QColor(215, 215, 215), 1));
        p.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
        p.setPen(Qt::black);
        p.drawText(QRectF(x - 40, plot.bottom() + 4, 80, fm.height()), Qt::AlignHCenter | Qt::AlignTop, QString::number(t, 'g', 3));
    }
    p.setPen(QPen(Qt::black, 1.2));
    p.setBrush(Qt::NoBrush);
    p.drawRect(plot);
    p.drawText(QRectF(plot.left(), plot.bottom() + fm.height() * 1.4, plot.width(), fm.height() * 1.2), Qt::AlignCenter, "t [s]");
    p.save();
    p.translate(box.left() + fm.height() * 0.1, plot.center().y());
    p.rotate(-90);
    p.drawText(QRectF(-plot.height() / 2, 0, plot.height(), fm.height() * 1.2), Qt::AlignCenter, panel.yLabel);
    p.restore();

    p.save();
    p.setClipRect(plot.adjusted(-2, -2, 2, 2));
    p.setRenderHint(QPainter::Antialiasing, true);
    for (std::size_t r = 0; r < runs.size(); ++r) {
        const std::vector<double>& values = runs[r].*panel.values;
        const std::vector<double>& t = runs[r].result.trajectory.t;
        if (values.empty() || values.size() != t.size()) continue;
        QPainterPath path;
        path.moveTo(X(t[0]), Y(values[0]));
        for (std::size_t k = 1; k < values.size(); ++k) path.lineTo(X(t[k]), Y(values[k]));
        p.setPen(QPen(plotColor(r), 2.2, r % 2 ? Qt::DashLine : Qt::SolidLine));
        p.drawPath(path);
    }
    p.restore();
}

}  // namespace

void paintLawComparison(QPainter& p, const QRectF& area, const LawComparisonPlot& plot) {
    p.save();
    p.fillRect(area, Qt::white);
    QFont font = p.font();
    font.setPointSizeF(std::max(7.0, area.height() / 58.0));
    p.setFont(font);
    const QFontMetricsF fm(font);
    const std::vector<LawRun>& runs = *plot.runs;

    double duration = 0, largestTorque = 0;
    std::vector<double> errors;
    for (const LawRun& r : runs) {
        if (!r.result.trajectory.t.empty()) duration = std::max(duration, r.result.trajectory.t.back());
        for (double v : r.torque) largestTorque = std::max(largestTorque, v);
        for (double v : r.error) errors.push_back(v);  // exact zeros (the start) do not set the range
    }
    if (!(duration > 0)) duration = 1;
    DecadeRange decades = decadesOf(errors);
    decades.lo = std::max(decades.lo, decades.hi - 12);  // below that, the bottom edge

    QFont titleFont = font;
    titleFont.setPointSizeF(font.pointSizeF() * 1.25);
    titleFont.setBold(true);
    p.setFont(titleFont);
    p.setPen(Qt::black);
    p.drawText(QRectF(area.left(), area.top() + 4, area.width(), fm.height() * 1.7), Qt::AlignCenter,
               QString("The laws compared: %1").arg(QString::fromStdString(plot.scene)));
    p.setFont(font);
    // the legend, one line across
    double x = area.left() + 20;
    const double ly = area.top() + fm.height() * 2.9;
    for (std::size_t r = 0; r < runs.size(); ++r) {
        p.setPen(QPen(plotColor(r), 2.5, r % 2 ? Qt::DashLine : Qt::SolidLine));
        p.drawLine(QPointF(x, ly - fm.ascent() / 3), QPointF(x + 30, ly - fm.ascent() / 3));
        p.setPen(Qt::black);
        const QString name = QString::fromUtf8(toString(runs[r].law)) + (runs[r].impossible.empty() ? "" : " (not possible)");
        p.drawText(QPointF(x + 36, ly), name);
        x += 36 + fm.horizontalAdvance(name) + 30;
    }
    const double top = area.top() + fm.height() * 3.8, half = area.width() / 2;
    const QString eu = QString::fromStdString(plot.errorUnit), tu = QString::fromStdString(plot.torqueUnit);
    paintPanel(p, QRectF(area.left(), top, half, area.bottom() - top),
               {"tracking error", "max_i |e_i| [" + eu + "]", true, double(decades.lo), double(decades.hi), &LawRun::error}, runs, duration);
    paintPanel(p, QRectF(area.left() + half, top, half, area.bottom() - top),
               {"torque", "max_i |τ_i| [" + tu + "]", false, 0.0, largestTorque > 0 ? largestTorque * 1.05 : 1.0, &LawRun::torque}, runs,
               duration);
    p.restore();
}

bool saveLawComparisonPlot(const LawComparisonPlot& plot, const QString& path, QString* error, QSize size) {
    return savePaintedPlot(
        path, size, "The laws compared: " + QString::fromStdString(plot.scene),
        [&](QPainter& painter, const QRectF& area) { paintLawComparison(painter, area, plot); }, error);
}

}  // namespace ll::ui
