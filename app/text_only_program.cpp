// lagrangelab's painting functions: it links neither Qt nor OpenSceneGraph, so each hands
// the whole command line over to lagrangelab-gui (app/graphics_handoff.hpp). main hands
// over before any work when commandPaints() says so; these are reached only if it did not.
#include <cstdio>
#include <cstdlib>

#include "app/commands.hpp"
#include "app/graphics_handoff.hpp"

namespace ll::cli {
namespace {

// _Exit: as if the exec had replaced the process; nothing of this one is to run on.
[[noreturn]] void handOver() {
    const int code = handOverToGraphicsProgram();
    std::fflush(nullptr);
    std::_Exit(code);
}

}  // namespace

int windowCommand(const Args&, const std::chrono::steady_clock::time_point&) { return handOverToGraphicsProgram(); }
int renderCommand(const Args&) { return handOverToGraphicsProgram(); }
int benchGui(const std::vector<std::string>&, int) { return handOverToGraphicsProgram(); }
int benchRender(const std::vector<std::string>&, int) { return handOverToGraphicsProgram(); }
int benchTypeset(const std::vector<std::string>&, int) { return handOverToGraphicsProgram(); }
int writeDerivationPages(const symbolic::DisplayDocument&, const std::string&, const std::string&, bool) {
    return handOverToGraphicsProgram();
}
void saveAccuracyPlot(const WorkPrecisionResult&, const std::string&) { handOver(); }

}  // namespace ll::cli
