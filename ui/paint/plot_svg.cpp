#include "ui/paint/plot_svg.hpp"

#include <algorithm>
#include <cmath>

#include <QBuffer>
#include <QPainter>
#include <QPainterPath>
#include <QSvgGenerator>

#include "core/io/atomic_file.hpp"
#include "ui/paint/round_step.hpp"

namespace ll::ui {

void writePlotSvg(const std::string& path, const QString& title, const QString& valueAxis, const std::vector<double>& times,
                  const std::vector<PlotCurve>& curves) {
    const QSize size(800, 450);
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    QSvgGenerator svg;
    svg.setOutputDevice(&buffer);
    svg.setSize(size);
    svg.setViewBox(QRect(QPoint(0, 0), size));
    svg.setTitle(title);
    {
        QPainter p(&svg);
        p.setRenderHint(QPainter::Antialiasing);
        p.fillRect(QRect(QPoint(0, 0), size), Qt::white);
        QFont font = p.font();
        font.setPixelSize(14);
        p.setFont(font);
        const int rows = static_cast<int>((curves.size() + 3) / 4);
        const QRectF plot(80, 40, size.width() - 110, size.height() - 110 - rows * 22);
        double t0 = times.empty() ? 0 : times.front(), t1 = times.empty() ? 1 : times.back();
        if (t1 <= t0) t1 = t0 + 1;
        double lo = 1e300, hi = -1e300;
        for (const PlotCurve& c : curves)
            for (double v : c.values)
                if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
        if (lo > hi) lo = 0, hi = 1;
        if (hi - lo < 1e-12 * std::max(1.0, std::abs(hi))) lo -= 0.5, hi += 0.5;
        const double yStep = roundStep((hi - lo) / 6), xStep = roundStep((t1 - t0) / 8);
        lo = std::floor(lo / yStep) * yStep, hi = std::ceil(hi / yStep) * yStep;
        const auto at = [&](double t, double v) {
            return QPointF(plot.left() + (t - t0) / (t1 - t0) * plot.width(), plot.bottom() - (v - lo) / (hi - lo) * plot.height());
        };
        p.setPen(QPen(QColor(20, 20, 30)));
        p.drawText(QRectF(0, 6, size.width(), 24), Qt::AlignHCenter, title);
        // Grid, ticks and their labels.
        for (double v = lo; v <= hi + 1e-9 * yStep; v += yStep) {
            const double y = at(t0, v).y();
            p.setPen(QPen(QColor(225, 228, 232), 1));
            p.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
            p.setPen(QColor(60, 60, 70));
            const QString label = QString::number(std::abs(v) < 1e-9 * yStep ? 0.0 : v, 'g', 6);
            p.drawText(QRectF(0, y - 10, plot.left() - 8, 20), Qt::AlignRight | Qt::AlignVCenter, label);
        }
        for (double t = std::ceil(t0 / xStep) * xStep; t <= t1 + 1e-9 * xStep; t += xStep) {
            const double x = at(t, lo).x();
            p.setPen(QPen(QColor(225, 228, 232), 1));
            p.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
            p.setPen(QColor(60, 60, 70));
            p.drawText(QRectF(x - 40, plot.bottom() + 4, 80, 20), Qt::AlignHCenter | Qt::AlignTop, QString::number(t, 'g', 6));
        }
        p.setPen(QPen(QColor(60, 60, 70), 1.2));
        p.drawRect(plot);
        p.drawText(QRectF(plot.left(), plot.bottom() + 24, plot.width(), 20), Qt::AlignHCenter, "t [s]");
        p.save();
        p.translate(18, plot.center().y());
        p.rotate(-90);
        p.drawText(QRectF(-plot.height() / 2, -10, plot.height(), 20), Qt::AlignCenter, valueAxis);
        p.restore();
        // The curves, then the legend below.
        p.setClipRect(plot);
        for (const PlotCurve& c : curves) {
            QPainterPath line;
            for (std::size_t k = 0; k < times.size() && k < c.values.size(); ++k) {
                const QPointF point = at(times[k], c.values[k]);
                if (k == 0) line.moveTo(point);
                else line.lineTo(point);
            }
            p.setPen(QPen(c.color, 1.8));
            p.drawPath(line);
        }
        p.setClipping(false);
        const double legendTop = plot.bottom() + 50, column = (size.width() - 40) / 4.0;
        for (std::size_t i = 0; i < curves.size(); ++i) {
            const QPointF corner(20 + (i % 4) * column, legendTop + static_cast<double>(i / 4) * 22);
            p.fillRect(QRectF(corner + QPointF(0, 4), QSizeF(18, 10)), curves[i].color);
            p.setPen(QColor(20, 20, 30));
            p.drawText(corner + QPointF(24, 14), curves[i].name);
        }
    }
    buffer.close();
    saveFileAtomically(path, bytes.toStdString(), Backup::None);
}

}  // namespace ll::ui
