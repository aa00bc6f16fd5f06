#pragma once
// The window as it is on screen once its last change has been drawn: a new frame of the 3D
// view requested and waited for, then the whole window grabbed until the picture no longer
// changes (the scripted window's --screenshot, lesson stills and videos).
#include <QImage>

namespace ll::ui {
class MainWindow;
}

namespace ll::cli {

QImage settledScreenshot(ui::MainWindow& window);

}  // namespace ll::cli
