#include "ui/paint/energy_inset.hpp"

#include <algorithm>
#include <cmath>

#include <QCoreApplication>
#include <QPainterPath>

namespace ll::ui {
namespace {

// PhET's energy colours: kinetic green, potential blue, total purple, work red.
const QColor kColours[4] = {QColor(0, 150, 60), QColor(30, 90, 220), QColor(140, 50, 170), QColor(210, 40, 40)};
const char* const kSubscripts[4] = {"kin", "pot", "", ""};
const char* const kLetters[4] = {"E", "E", "E", "W"};

double niceStep(double x) {
    const double decade = std::pow(10.0, std::floor(std::log10(x)));
    for (double m : {1.0, 2.0, 5.0})
        if (m * decade >= x * 0.999) return m * decade;
    return 10 * decade;
}

QString number(double value, double step) {
    const int decimals = std::clamp(static_cast<int>(-std::floor(std::log10(step) + 1e-9)), 0, 6);
    return QString::number(std::abs(value) < step * 1e-6 ? 0.0 : value, 'f', decimals);
}

// "E" then "kin" as a subscript; returns the width drawn.
double drawSymbol(QPainter& p, QPointF baseline, const char* letter, const char* subscript, int pixels) {
    QFont font = p.font();
    font.setPixelSize(pixels);
    font.setItalic(true);
    p.setFont(font);
    p.drawText(baseline, QString::fromLatin1(letter));
    double width = QFontMetricsF(font).horizontalAdvance(QString::fromLatin1(letter));
    if (*subscript) {
        QFont small = font;
        small.setItalic(false);
        small.setPixelSize(std::max(6, pixels * 7 / 10));
        p.setFont(small);
        p.drawText(baseline + QPointF(width + 1, pixels * 0.25), QString::fromLatin1(subscript));
        width += 1 + QFontMetricsF(small).horizontalAdvance(QString::fromLatin1(subscript));
    }
    font.setItalic(false);
    p.setFont(font);
    return width;
}

}  // namespace

EnergyInset::EnergyInset(const Trajectory& trajectory, bool showWork, QSize size, int fontPixels)
    : background_(size, QImage::Format_ARGB32_Premultiplied), showWork_(showWork), fontPixels_(fontPixels) {
    const std::vector<double>* series[4] = {&trajectory.Ekin, &trajectory.Epot, &trajectory.E, &trajectory.work};
    const int curves = showWork_ ? 4 : 3;
    t0_ = trajectory.t.empty() ? 0.0 : trajectory.t.front();
    t1_ = trajectory.t.empty() ? 1.0 : std::max(trajectory.t.back(), t0_ + 1e-9);
    low_ = 1e300, high_ = -1e300;
    for (int c = 0; c < curves; ++c)
        for (double v : *series[c]) low_ = std::min(low_, v), high_ = std::max(high_, v);
    if (low_ > high_) low_ = 0, high_ = 1;
    const double pad = std::max(0.06 * (high_ - low_), 1e-9 * std::max(1.0, std::abs(high_)));
    low_ -= pad, high_ += pad;

    const double f = fontPixels_, margin = 0.6 * f;
    background_.fill(Qt::transparent);
    QPainter p(&background_);
    p.setRenderHint(QPainter::Antialiasing);
    QFont font = p.font();
    font.setPixelSize(fontPixels_);
    p.setFont(font);
    p.setPen(QPen(QColor(150, 150, 160), 1));
    p.setBrush(QColor(255, 255, 255, 225));
    p.drawRoundedRect(QRectF(0.5, 0.5, size.width() - 1, size.height() - 1), f * 0.5, f * 0.5);

    // Two legend rows on top, tick labels left and below.
    const double yStep = niceStep((high_ - low_) / 5), tStep = niceStep((t1_ - t0_) / 5);
    const QFontMetricsF metrics(font);
    double labelWidth = 0;
    for (double v = std::ceil(low_ / yStep) * yStep; v <= high_; v += yStep)
        labelWidth = std::max(labelWidth, metrics.horizontalAdvance(number(v, yStep) + " J"));
    plot_ = QRectF(margin + labelWidth + 0.4 * f, margin + 2.9 * f + 0.4 * f, 0, 0);
    plot_.setRight(size.width() - margin - 1.3 * f);  // room for the last time label
    plot_.setBottom(size.height() - margin - 1.3 * f);

    p.setPen(QPen(QColor(225, 225, 230), 1));
    p.setBrush(Qt::NoBrush);
    for (double v = std::ceil(low_ / yStep) * yStep; v <= high_; v += yStep) {
        const double y = toPixel(t0_, v).y();
        p.setPen(QPen(QColor(225, 225, 230), 1));
        p.drawLine(QPointF(plot_.left(), y), QPointF(plot_.right(), y));
        p.setPen(QColor(70, 70, 80));
        p.drawText(QRectF(margin, y - f, labelWidth, 2 * f), Qt::AlignRight | Qt::AlignVCenter, number(v, yStep) + " J");
    }
    for (double t = std::ceil(t0_ / tStep) * tStep; t <= t1_ + 1e-9 * tStep; t += tStep) {
        const double x = toPixel(t, low_).x();
        p.setPen(QPen(QColor(225, 225, 230), 1));
        p.drawLine(QPointF(x, plot_.top()), QPointF(x, plot_.bottom()));
        p.setPen(QColor(70, 70, 80));
        p.drawText(QRectF(x - 3 * f, plot_.bottom() + 0.15 * f, 6 * f, 1.2 * f), Qt::AlignHCenter | Qt::AlignTop, number(t, tStep) + " s");
    }
    p.setPen(QPen(QColor(120, 120, 130), 1));
    p.drawRect(plot_);

    // The curves, at most two points per pixel column.
    const int n = static_cast<int>(trajectory.t.size());
    const int stride = std::max(1, n / std::max(1, 2 * static_cast<int>(plot_.width())));
    p.setClipRect(plot_.adjusted(-1, -1, 1, 1));
    for (int c = 0; c < curves; ++c) {
        QPainterPath path;
        for (int k = 0; k < n; k += stride) {
            const QPointF point = toPixel(trajectory.t[k], (*series[c])[k]);
            if (k == 0) path.moveTo(point);
            else path.lineTo(point);
        }
        if (n > 0) path.lineTo(toPixel(trajectory.t[n - 1], (*series[c])[n - 1]));
        p.setPen(QPen(kColours[c], c == 2 ? 2.2 : 1.6));
        p.drawPath(path);
    }
}

QPointF EnergyInset::toPixel(double t, double energy) const {
    return {plot_.left() + (t - t0_) / (t1_ - t0_) * plot_.width(), plot_.bottom() - (energy - low_) / (high_ - low_) * plot_.height()};
}

void EnergyInset::paint(QPainter& painter, QPoint at, double t, const std::array<double, 4>& values) const {
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    painter.drawImage(at, background_);
    painter.translate(at);
    const int curves = showWork_ ? 4 : 3;
    // Cursor and a dot on each curve.
    const double x = toPixel(std::clamp(t, t0_, t1_), low_).x();
    painter.setPen(QPen(QColor(40, 40, 50), 1.5));
    painter.drawLine(QPointF(x, plot_.top()), QPointF(x, plot_.bottom()));
    painter.setPen(Qt::NoPen);
    for (int c = 0; c < curves; ++c) {
        painter.setBrush(kColours[c]);
        painter.drawEllipse(toPixel(std::clamp(t, t0_, t1_), values[c]), 0.22 * fontPixels_, 0.22 * fontPixels_);
    }
    // Legend: symbol, value and unit, two per row.
    const double f = fontPixels_, margin = 0.6 * f;
    const double step = niceStep((high_ - low_) / 40);
    const double column = (background_.width() - 2 * margin) / 2;
    for (int c = 0; c < curves; ++c) {
        const QPointF baseline(margin + (c % 2) * column, margin + (c / 2 + 1) * 1.45 * f - 0.2 * f);
        painter.setBrush(kColours[c]);
        painter.setPen(Qt::NoPen);
        painter.drawRect(QRectF(baseline.x(), baseline.y() - 0.55 * f, 0.8 * f, 0.4 * f));
        painter.setPen(QColor(30, 30, 40));
        const double w = drawSymbol(painter, baseline + QPointF(f, 0), kLetters[c], kSubscripts[c], fontPixels_);
        painter.drawText(baseline + QPointF(f + w + 0.35 * f, 0),
                         QCoreApplication::translate("EnergyInset", "%1 J").arg(number(values[c], step)));
    }
    painter.restore();
}

}  // namespace ll::ui
