#pragma once
// One simulation run of a scene, shaped for a GUI worker thread as much as for the
// CLI: inputs are copied in, progress is reported through a callback, a flag
// cancels, and the result is plain data (partial when cancelled or failed).
#include <atomic>
#include <functional>

#include "core/model/scene.hpp"
#include "core/simulation/trajectory.hpp"

namespace ll {

using ProgressCallback = std::function<void(double fraction)>;  // 0..1, from the worker thread

// Integrates the scene's equations of motion from its initial state over
// settings.duration, recording t, q, q̇, E_kin, E_pot, E and the work of Q at
// settings.outputRate. The scene must be valid (requireValidScene); an unknown
// integrator throws std::invalid_argument before anything runs. A Lagrangian scene is
// derived and compiled first (LagrangianOde); its input errors (E_kin not quadratic,
// dependent coordinates, a conservative Q) throw InputError before anything runs.
SimulationResult simulate(const Scene& scene, const SimulationSettings& settings,
                          const ProgressCallback& progress = {}, const std::atomic<bool>* cancel = nullptr);

inline SimulationResult simulate(const Scene& scene) { return simulate(scene, scene.simulation); }

// Output times 0, 1/rate, ..., duration (the last one exactly duration).
std::vector<double> outputTimes(double duration, double rate);

// CPU time of the calling thread [s].
double threadCpuSeconds();

}  // namespace ll
