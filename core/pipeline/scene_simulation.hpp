#pragma once
// From a scene to a simulation, for callers on any thread (the CLI, the window's
// workers, tests): the one place where a Lagrangian system is derived and compiled
// (under the GiNaC lock) into the plain data core/simulation runs on.
#include <atomic>
#include <optional>

#include "core/kinematics/body_poses.hpp"

#include "core/model/scene.hpp"
#include "core/simulation/simulate.hpp"
#include "core/simulation/work_precision.hpp"

namespace ll {

// A scene made ready to simulate and to draw, its expressions compiled once: the
// simulation's input and, for a typed Lagrangian, its bodies' poses (core/visual draws
// them without GiNaC).
struct PreparedScene {
    SimulationInput simulation;
    std::optional<BodyPoses> bodies;
};
PreparedScene prepareScene(const Scene& scene);

// A copy of the scene and, for a Lagrangian scene, its B, C, g, Q and energies derived
// with exact numbers and compiled. The scene must be valid (requireValidScene); a
// Lagrangian's input errors (E_kin not quadratic, dependent coordinates, a conservative
// Q) throw InputError naming the field. Takes the GiNaC lock for a Lagrangian scene.
SimulationInput prepareSimulation(const Scene& scene);

// prepareSimulation, then simulate() (core/simulation/simulate.hpp).
SimulationResult simulate(const Scene& scene, const SimulationSettings& settings, const ProgressCallback& progress = {},
                          const std::atomic<bool>* cancel = nullptr);
inline SimulationResult simulate(const Scene& scene) { return simulate(scene, scene.simulation); }

// prepareSimulation, then runWorkPrecision() (core/simulation/work_precision.hpp).
WorkPrecisionResult runWorkPrecision(const Scene& scene, const WorkPrecisionSettings& settings, const WorkPrecisionProgress& progress = {},
                                     const std::atomic<bool>* cancel = nullptr);

}  // namespace ll
