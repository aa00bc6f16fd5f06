#pragma once
// A small energy plot to lay over an animation frame: E_kin (green), E_pot (blue), the
// total E (purple) and, when the scene has friction or inputs, the work W of those
// forces (red), over the whole trajectory, with a cursor and the current values (J) at
// the frame's time. Colours follow PhET's energy plots. The axes and curves are drawn
// once into a cached image; each frame paints the cache, the cursor and the legend.
// Needs a QGuiApplication (fonts); headless, QT_QPA_PLATFORM=offscreen.
#include <array>

#include <QImage>
#include <QPainter>
#include <QSize>

#include "core/simulation/trajectory.hpp"

namespace ll::ui {

class EnergyInset {
public:
    // `size` in pixels; `fontPixels` the legend's text height.
    EnergyInset(const Trajectory& trajectory, bool showWork, QSize size, int fontPixels);

    QSize size() const { return background_.size(); }
    // Paints the inset with its top-left corner at `at`: the cursor at time t, the
    // values E_kin, E_pot, E, W at t in the legend.
    void paint(QPainter& painter, QPoint at, double t, const std::array<double, 4>& values) const;

private:
    QImage background_;
    QRectF plot_;  // the plot area inside the inset
    double t0_, t1_, low_, high_;
    bool showWork_;
    int fontPixels_;

    QPointF toPixel(double t, double energy) const;
};

}  // namespace ll::ui
