#pragma once
// The work–precision plot: two log–log panels, final-state error versus CPU time and
// energy drift versus CPU time, one coloured curve per integrator with a legend and
// decade ticks. Painted with QPainter, so the same code draws into a GUI widget, a
// PNG (QImage) or an SVG (QSvgGenerator). Needs a QGuiApplication (fonts); headless,
// set QT_QPA_PLATFORM=offscreen before constructing it.
#include <QPainter>
#include <QRectF>
#include <QSize>
#include <QString>

#include <vector>

#include "core/simulation/work_precision.hpp"

namespace ll::ui {

// `tickLabels` (optional): the boxes of the decade labels drawn, for tests. On a small
// area only every 2nd or 3rd decade is labelled, so labels never overlap.
void paintWorkPrecision(QPainter& painter, const QRectF& area, const WorkPrecisionResult& result,
                        std::vector<QRectF>* tickLabels = nullptr);

// Writes `path` as SVG or PNG by its suffix (.svg, .png), atomically (saveFileAtomically,
// no .bak). On failure returns false and says why in *error.
bool saveWorkPrecisionPlot(const WorkPrecisionResult& result, const QString& path, QString* error = nullptr, QSize size = QSize(1500, 680));

}  // namespace ll::ui
