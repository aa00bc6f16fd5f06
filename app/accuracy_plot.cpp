// The log–log plot of `lagrangelab accuracy SCENE --out plot.svg|png`, rendered headless
// (ui/work_precision_plot).
#include <stdexcept>

#include "app/commands.hpp"
#include "app/offscreen_gui.hpp"
#include "ui/paint/work_precision_plot.hpp"

namespace ll::cli {

void saveAccuracyPlot(const WorkPrecisionResult& result, const std::string& path) {
    const auto app = makeGuiApplication();  // fonts
    QString error;
    if (!ui::saveWorkPrecisionPlot(result, QString::fromStdString(path), &error)) throw std::runtime_error(error.toStdString());
}

}  // namespace ll::cli
