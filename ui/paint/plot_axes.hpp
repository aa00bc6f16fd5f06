#pragma once
// What the painted plots share (the work–precision plot, the law comparison): their
// colours, decade axes with raised-exponent labels, and saving a painting as SVG or PNG.
#include <functional>
#include <vector>

#include <QColor>
#include <QPainter>
#include <QPointF>
#include <QRectF>
#include <QSize>
#include <QString>

namespace ll::ui {

// The i-th series' colour (ten, then again).
QColor plotColor(std::size_t i);

struct DecadeRange {
    int lo = 0, hi = 1;  // decades 10^lo .. 10^hi
};
// The decades that hold every positive finite value ({-1, 0} when there is none).
DecadeRange decadesOf(const std::vector<double>& values);

// "10" with a raised exponent, centred (align = 0), right-aligned (1) at `anchor`; the
// box it takes, drawn unless `draw` is false.
QRectF drawPowerOfTen(QPainter& painter, QPointF anchor, int exponent, int align, bool draw = true);

// Every how many decades a label fits: labels `size` long (with a gap) on an axis
// `length` long over `decades` decades.
int labelStep(double length, int decades, double size);

// Paints into an SVG or PNG by the path's suffix (.svg, .png) at `size` and writes it
// atomically (saveFileAtomically, no .bak). On failure returns false and says why in *error.
bool savePaintedPlot(const QString& path, QSize size, const QString& title, const std::function<void(QPainter&, const QRectF&)>& paint,
                     QString* error);

}  // namespace ll::ui
