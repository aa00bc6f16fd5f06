#pragma once
// The plot of `lagrangelab compare-laws SCENE --out plot.svg|png`: the largest tracking
// error max_i |e_i(t)| (logarithmic) and the largest torque max_i |τ_i(t)| (linear)
// against time, one coloured curve per law, a law the robot cannot carry out named in the
// legend. Painted with QPainter (needs a QGuiApplication for fonts).
#include <string>
#include <vector>

#include <QPainter>
#include <QRectF>
#include <QSize>
#include <QString>

#include "core/pipeline/law_comparison.hpp"

namespace ll::ui {

struct LawComparisonPlot {
    std::string scene;               // its name, for the title
    std::string errorUnit = "rad";   // of e (rad, m, or "rad, m" for a mixed robot)
    std::string torqueUnit = "N·m";  // of τ
    const std::vector<LawRun>* runs = nullptr;
};

void paintLawComparison(QPainter& painter, const QRectF& area, const LawComparisonPlot& plot);

// Writes `path` as SVG or PNG by its suffix; on failure returns false and says why in *error.
bool saveLawComparisonPlot(const LawComparisonPlot& plot, const QString& path, QString* error = nullptr, QSize size = QSize(1500, 640));

}  // namespace ll::ui
