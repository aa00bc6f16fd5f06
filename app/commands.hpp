#pragma once
// The `lagrangelab <command>` entry points. Each returns the process exit code:
// 0 success, 2 bad input (scene or command line), 3 the simulation stopped early.
#include <chrono>
#include <string>
#include <vector>

namespace ll {
struct WorkPrecisionResult;
namespace present {
struct DisplayDocument;
}  // namespace present
}  // namespace ll

namespace ll::cli {

using Args = std::vector<std::string>;

int evalCommand(const Args& args);
int simulateCommand(const Args& args);
int integratorsCommand(const Args& args);
int accuracyCommand(const Args& args);
int deriveCommand(const Args& args);
int renderCommand(const Args& args);
int reportCommand(const Args& args);
int codegenCommand(const Args& args);
int checkCommand(const Args& args);
int compareLawsCommand(const Args& args);
int checkAnswerCommand(const Args& args);
int exerciseCommand(const Args& args);
int gradeCommand(const Args& args);
int importCommand(const Args& args);
int exportUrdfCommand(const Args& args);
// A lesson's views as a PDF, PNGs or videos of the presented window (app/command_lesson.cpp).
int lessonCommand(const Args& args);
// The painting parts: each starts Qt (offscreen without a display) for its own work.
// derive --format pdf|svg|png: the typeset pages of a display document (app/derive_pages.cpp).
int writeDerivationPages(const present::DisplayDocument& display, const std::string& format, const std::string& outPath, bool timings);
// accuracy --out: the work–precision plot, .svg or .png (app/accuracy_plot.cpp).
void saveAccuracyPlot(const WorkPrecisionResult& result, const std::string& path);
// The desktop window: `lagrangelab [SCENE] [--screenshot FILE.png …]` (app/window_command.cpp).
int windowCommand(const Args& args, const std::chrono::steady_clock::time_point& processStart);

}  // namespace ll::cli
