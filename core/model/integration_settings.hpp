#pragma once
// How an ODE is integrated: which integrator (core/simulation/integrators.hpp lists them),
// its tolerances, its (first) step and how many steps it may take. A scene's simulation
// settings extend these with the run's length and output rate (core/model/scene.hpp), so
// the two never disagree.
#include <string>

namespace ll {

struct IntegrationSettings {
    std::string integrator = "dopri5";
    double absTol = 1e-8;
    double relTol = 1e-8;
    double dt = 1e-3;  // fixed step, or the first trial step of adaptive methods [s]
    long maxSteps = 20'000'000;
    // Explicit adaptive methods stop with an IntegrationError recommending rosenbrock4
    // when their step size is pinned at the stability limit of a mode far faster than
    // the rest of the motion (core/simulation/integrators.cpp, StiffnessMonitor). Not a
    // scene-file field: the work–precision reference turns it off (it must resolve every mode).
    bool detectStiffness = true;
};

}  // namespace ll
