#pragma once
// How a derivation reads, decided once for every front end (the CLI's `derive`, the
// window's derivation view): combined angles (c12), s_i² or c_i² eliminated whichever
// is shorter, entries grouped by masses (by velocities for C, ω, v_c and E_kin; by the
// parameters for a hand-typed Lagrangian), scene decimals shown as decimals, and each
// equation in B q̈ + C q̇ + g = Q order. Rendered as
//   Text   the steps as a student reads them in a terminal (Unicode)
//   Latex  a complete LaTeX document
//   Json   every step's items with name, latex, text and a re-parsable plain `expr`,
//          plus top-level B, C, g, Q, Ekin, Epot, the actuation and warnings.
// Takes the GiNaC lock; the caller must hold it too while it owns the Derivation.
#include <string>

#include "core/symbolic/derivation.hpp"

namespace ll::symbolic {

enum class DocumentFormat { Text, Latex, Json };

// modeName ("parameters", "numeric", "symbolic") is recorded in the JSON.
std::string derivationDocument(const Derivation& derivation, DocumentFormat format, const std::string& modeName);

}  // namespace ll::symbolic
