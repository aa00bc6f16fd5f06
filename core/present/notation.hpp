#pragma once
// The textbook a derivation is written for: the letters of the dynamic model differ, the
// model does not. The notes' own (the default) write B(q) q̈ + C q̇ + g = Q with
// generalized forces Q; Siciliano et al. B(q) q̈ + C q̇ + g = τ; Spong et al.
// D(q) q̈ + C q̇ + g = τ; Craig M(Θ) Θ̈ + V(Θ, Θ̇) + G(Θ) = τ, with V = C Θ̇ and
// modified DH parameters.
#include <optional>
#include <string>
#include <string_view>

namespace ll::present {

enum class Notation { Notes, Siciliano, Spong, Craig };

// "notes", "siciliano", "spong", "craig"; nullopt for anything else.
std::optional<Notation> notationNamed(std::string_view name);
const char* notationName(Notation notation);

struct NotationSymbols {
    std::string mass;             // B, D, M: the mass matrix's letter …
    std::string massEntry;        // b, d, m: … and its entries'
    std::string gravity;          // g, G
    std::string force;            // Q, τ: the generalized forces (text)
    std::string forceLatex;       // Q, \tau
    std::string coordinate;       // q, θ: a joint variable's letter (text)
    std::string coordinateLatex;  // q, \theta
    std::string vectorLatex;      // q, \Theta: the vector of joint variables (B(q), M(Θ))
    bool modifiedDH = false;      // the DH convention the textbook uses
};

const NotationSymbols& notationSymbols(Notation notation);

}  // namespace ll::present
