// lagrangelab: Euler–Lagrange modelling of serial robots, from the command line.
#include <cstdio>
#include <iostream>
#include <string>

#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "core/model/diagnostics.hpp"

namespace {

const char* kUsage =
    "usage: lagrangelab <command> [arguments]\n"
    "\n"
    "commands:\n"
    "  eval SCENE --q v1,... --qd v1,... [--t T] [--tau v1,...]\n"
    "      B, C, g, Q, q̈, E_kin, E_pot at one state, as JSON\n"
    "  simulate SCENE [--duration T] [--integrator NAME] [--abs-tol X] [--rel-tol X] [--dt X]\n"
    "           [--output-rate HZ] [--out FILE.csv|FILE.json]\n"
    "      integrate the equations of motion; trajectory to --out or CSV on stdout, summary on stderr\n"
    "  derive SCENE [--format text|latex|json] [--steps 0-8] [--symbolic] [--numeric] [--timings]\n"
    "      the model step by step as the course notes derive it (symbolic, GiNaC)\n"
    "  render SCENE --out FILE.mp4|.webm|.gif|.png|FOLDER [--duration T] [--fps F] [--size WxH]\n"
    "         [--camera front|side|top|iso|az,el[,dist]] [--speed X] [--overlay time,energy,name|none]\n"
    "         [--trail on|off] [--frames on|off] [--at T] [--msaa 0|2|4|8]\n"
    "      simulate and render the 3D scene headless (no X server needed) to a video, a still or PNG frames\n"
    "  integrators\n"
    "      the integrators with order, kind and when to use each\n"
    "  accuracy SCENE [--integrators a,b,...] [--tolerances 1e-3..1e-12] [--steps dt1,dt2,...] [--duration T]\n"
    "           [--repeats N] [--reference-tol X] [--out plot.svg|png] [--csv FILE]\n"
    "      work-precision: error, energy drift, CPU time, evaluations and steps per integrator and setting\n"
    "  bench [SCENE...] [--batches N] [--rhs | --derive | --render]\n"
    "      median times of B, C, g, forward/inverse dynamics and one simulated second, beside KDL\n"
    "      (--rhs: one right-hand side of the PUMA 560 with no effects, gravity only, all effects;\n"
    "       --derive: the whole symbolic derivation per parameter mode;\n"
    "       --render: headless export of 10 s of the PUMA 560 to MP4, render-only frames/s, peak memory)\n"
    "\n"
    "exit codes: 0 success, 2 bad input, 3 simulation stopped early, 130 interrupted (render: nothing written)\n";

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "help") {
        std::fputs(kUsage, argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    const std::string command = argv[1];
    const ll::cli::Args args(argv + 2, argv + argc);
    try {
        if (command == "eval") return ll::cli::evalCommand(args);
        if (command == "simulate") return ll::cli::simulateCommand(args);
        if (command == "integrators") return ll::cli::integratorsCommand(args);
        if (command == "bench") return ll::cli::benchCommand(args);
        if (command == "accuracy") return ll::cli::accuracyCommand(args);
        if (command == "derive") return ll::cli::deriveCommand(args);
        if (command == "render") return ll::cli::renderCommand(args);
        std::fprintf(stderr, "error: unknown command '%s'\n\n%s", command.c_str(), kUsage);
        return 2;
    } catch (const ll::InputError& e) {
        for (const ll::Diagnostic& d : e.diagnostics())
            if (d.severity == ll::Severity::Error) std::cerr << "error: " << d.field << ": " << d.message << '\n';
        return 2;
    } catch (const ll::cli::UsageError& e) {
        std::cerr << "error: " << e.what() << '\n';
        return 2;
    } catch (const std::invalid_argument& e) {
        std::cerr << "error: " << e.what() << '\n';
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << '\n';
        return 1;
    }
}
