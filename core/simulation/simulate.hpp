#pragma once
// One simulation run of a scene, shaped for a GUI worker thread as much as for the
// CLI: inputs are copied in, progress is reported through a callback, a flag
// cancels, and the result is plain data (partial when cancelled or failed). Nothing
// here touches GiNaC: a Lagrangian system arrives compiled (SimulationInput).
#include <atomic>
#include <functional>
#include <optional>

#include "core/dynamics/compiled_lagrangian.hpp"
#include "core/model/scene.hpp"
#include "core/simulation/trajectory.hpp"

namespace ll {

// Everything a run needs, as plain data owned by the run: a copy of the scene and, for
// a system typed as a Lagrangian, its compiled B, C, g, Q and energies. The pipeline
// (core/pipeline/scene_simulation: prepareSimulation) derives and compiles them under
// the GiNaC lock.
struct SimulationInput {
    Scene scene;
    std::optional<CompiledLagrangian> lagrangian;  // required when scene.lagrangian is set
};

using ProgressCallback = std::function<void(double fraction)>;  // 0..1, from the worker thread

// Integrates the scene's equations of motion from its initial state over
// settings.duration, recording t, q, q̇, E_kin, E_pot, E and the work of Q at
// settings.outputRate. The scene must be valid (requireValidScene). Throws
// std::invalid_argument before anything runs for an unknown integrator, a Lagrangian
// scene without its compiled system, or an initial state of the wrong size. The input
// is taken by value: the caller may change or destroy its own copy meanwhile.
SimulationResult simulate(SimulationInput input, const SimulationSettings& settings, const ProgressCallback& progress = {},
                          const std::atomic<bool>* cancel = nullptr);

// Output times 0, 1/rate, ..., duration (the last one exactly duration).
std::vector<double> outputTimes(double duration, double rate);

// CPU time of the calling thread [s].
double threadCpuSeconds();

}  // namespace ll
