#pragma once
// A line plot over time written as vector SVG (QSvgGenerator): the lab report's energy
// and joint plots, readable without the program. Axes with round ticks and units, one
// colour per curve, a legend below the plot. Needs a QGuiApplication (fonts).
#include <string>
#include <vector>

#include <QColor>
#include <QString>

namespace ll::ui {

struct PlotCurve {
    QString name;
    QColor color;
    std::vector<double> values;  // one per time
};

// Writes the plot to `path` (atomically); throws std::runtime_error naming the path when
// it cannot be written.
void writePlotSvg(const std::string& path, const QString& title, const QString& valueAxis, const std::vector<double>& times,
                  const std::vector<PlotCurve>& curves);

}  // namespace ll::ui
