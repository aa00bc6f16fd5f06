#pragma once
// Two programs run LagrangeLab's commands. lagrangelab-gui links Qt and OpenSceneGraph and
// runs all of them; lagrangelab links only the core, statically (about 7 ms to start instead of 55)
// and hands every command that paints over to lagrangelab-gui: exec, so the process id,
// arguments, environment and standard streams stay the same.
#include <filesystem>

namespace ll::cli {

// Keeps main's argv for a handover.
void rememberCommandLine(char** argv);

// lagrangelab-gui: $LAGRANGELAB_GUI when set; else beside the running program (build tree),
// else PREFIX/libexec/lagrangelab/lagrangelab-gui (installed).
std::filesystem::path graphicsProgram();

// lagrangelab, as a user starts it (bench --gui's start to first frame): beside the
// running program (build tree), else PREFIX/bin/lagrangelab seen from libexec/lagrangelab/.
std::filesystem::path textProgram();

// Replaces this process with lagrangelab-gui on the remembered command line. Returns only
// when that fails, with exit code 1 after one error line.
int handOverToGraphicsProgram();

// lagrangelab-gui, first thing: forgets that it was handed a command line, so that what
// it starts (bench --gui starts lagrangelab) may hand over again.
void clearHandoverMark();

// An X or Wayland display to open the window on.
bool hasDisplay();

}  // namespace ll::cli
