#include "ui/paint/plot_axes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <QBuffer>
#include <QFileInfo>
#include <QFontMetricsF>
#include <QImage>
#include <QSvgGenerator>

#include "core/io/atomic_file.hpp"

namespace ll::ui {

QColor plotColor(std::size_t i) {
    static const QColor kPalette[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xff, 0x7f, 0x0e), QColor(0x2c, 0xa0, 0x2c),
                                      QColor(0xd6, 0x27, 0x28), QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b),
                                      QColor(0xe3, 0x77, 0xc2), QColor(0x7f, 0x7f, 0x7f), QColor(0xbc, 0xbd, 0x22),
                                      QColor(0x17, 0xbe, 0xcf)};
    return kPalette[i % std::size(kPalette)];
}

DecadeRange decadesOf(const std::vector<double>& values) {
    double lo = INFINITY, hi = -INFINITY;
    for (double v : values)
        if (v > 0 && std::isfinite(v)) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    if (!std::isfinite(lo)) return {-1, 0};
    DecadeRange r{static_cast<int>(std::floor(std::log10(lo))), static_cast<int>(std::ceil(std::log10(hi)))};
    if (r.hi <= r.lo) r.hi = r.lo + 1;
    return r;
}

QRectF drawPowerOfTen(QPainter& p, QPointF anchor, int exponent, int align, bool draw) {
    const QFont base = p.font();
    QFont small = base;
    small.setPointSizeF(base.pointSizeF() * 0.72);
    const QString mantissa = "10", power = QString::number(exponent).replace('-', QChar(0x2212));
    const double w1 = QFontMetricsF(base).horizontalAdvance(mantissa), w2 = QFontMetricsF(small).horizontalAdvance(power);
    const double ascent = QFontMetricsF(base).ascent();
    double x = align == 0 ? anchor.x() - (w1 + w2) / 2 : anchor.x() - (w1 + w2);
    const double y = anchor.y();
    if (draw) {
        p.drawText(QPointF(x, y), mantissa);
        p.setFont(small);
        p.drawText(QPointF(x + w1, y - 0.45 * ascent), power);
        p.setFont(base);
    }
    return QRectF(x, y - 0.45 * ascent - QFontMetricsF(small).ascent(), w1 + w2,
                  0.45 * ascent + QFontMetricsF(small).ascent() + QFontMetricsF(base).descent());
}

int labelStep(double length, int decades, double size) {
    const double spacing = length / std::max(decades, 1);
    return spacing > 0 ? std::max(1, static_cast<int>(std::ceil(size / spacing))) : 1;
}

bool savePaintedPlot(const QString& path, QSize size, const QString& title, const std::function<void(QPainter&, const QRectF&)>& paint,
                     QString* error) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix != "svg" && suffix != "png") {
        if (error) *error = "unknown plot format '." + suffix + "' (use .svg or .png)";
        return false;
    }
    // Rendered into memory, then written by the one atomic-save routine.
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    if (suffix == "svg") {
        QSvgGenerator svg;
        svg.setOutputDevice(&buffer);
        svg.setSize(size);
        svg.setViewBox(QRect(QPoint(0, 0), size));
        svg.setTitle(title);
        QPainter painter;
        if (!painter.begin(&svg)) {
            if (error) *error = "cannot render the plot for " + path;
            return false;
        }
        paint(painter, QRectF(QPointF(0, 0), size));
        painter.end();
    } else {
        QImage image(size, QImage::Format_ARGB32_Premultiplied);
        image.fill(Qt::white);
        QPainter painter(&image);
        painter.setRenderHint(QPainter::TextAntialiasing, true);
        paint(painter, QRectF(QPointF(0, 0), size));
        painter.end();
        if (!image.save(&buffer, "PNG")) {
            if (error) *error = "cannot encode the plot for " + path;
            return false;
        }
    }
    try {
        saveFileAtomically(path.toStdString(), buffer.data().toStdString(), Backup::None);
    } catch (const std::runtime_error& e) {
        if (error) *error = QString::fromStdString(e.what());
        return false;
    }
    return true;
}

}  // namespace ll::ui
