#pragma once
// No result is silently non-finite: a scene whose numbers are each finite can still
// overflow in B, C, g, Q, q̈ or an energy (a spring's rest at 1e300 squares to inf in
// E_pot). This finds the first such quantity, so `eval`, the simulation and the
// validation refuse the state and name it instead of printing inf or null.
#include <optional>
#include <string>

#include <Eigen/Core>

#include "core/dynamics/compiled_lagrangian.hpp"
#include "core/model/diagnostics.hpp"

namespace ll {

// An error whose field is the quantity ("B", "C", "g", "Q", "qdd", "Ekin" or "Epot",
// the names `eval` prints) and whose message gives the first non-finite entry, the
// state and `where` (MessageId::WhereInitialState, "at the initial state (t = 0)", or
// WhereAtTime, "at t = 0.5"); nothing when all are finite. An empty qdd is not checked.
std::optional<Diagnostic> nonFiniteTerm(const ModelTerms& terms, const Eigen::VectorXd& qdd, const Eigen::VectorXd& q,
                                        const Eigen::VectorXd& qd, const Message& where);

}  // namespace ll
