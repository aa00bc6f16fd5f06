#pragma once
// One answer to "is this scene valid, and if not, which fields and why": what the
// window's editor asks after every edit, and what the CLI reports before it runs.
// It runs every check of every layer: the fields (core/model/validation), a regular
// mass matrix and a known integrator (core/simulation/scene_validation), and for a
// system typed as a Lagrangian its derivation's input checks (E_kin quadratic in q̇,
// B positive definite at the initial state, no conservative force in Q, expressions
// that parse), under the GiNaC lock. Safe to call from any thread; returns plain data.
#include <vector>

#include "core/model/diagnostics.hpp"
#include "core/model/scene.hpp"

namespace ll {

// Errors and warnings, each naming its field; no error means the scene can be derived
// and simulated.
std::vector<Diagnostic> checkScene(const Scene& scene);

}  // namespace ll
