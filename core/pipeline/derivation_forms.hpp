#pragma once
// A robot's derivation in one of two forms, for the CLI's `derive --form`:
//   expanded    the course notes' steps 0–8 with every entry fully expanded (textbook
//               closed forms; the size grows exponentially with the joints)
//   structured  B, C, g as short sums over named link quantities (structured_dynamics.hpp;
//               polynomial cost)
//   auto        expanded when that is cheap (small robots), else structured; the
//               document says which and why.
// `entries` (B11, C23, g4) shows only those; with the expanded (or auto) form they are
// expanded on demand from the structured form, memoised, with their term counts.
// A hand-typed Lagrangian keeps its own path (expanded). `verify` compares the
// structured form, the expanded form when it is cheap and the numeric core at random
// states. Thread-safe like deriveDocument (scene_derivation.hpp).
#include <string>
#include <vector>

#include "core/pipeline/scene_derivation.hpp"

namespace ll {

enum class DerivationForm { Auto, Structured, Expanded };

struct FormRequest {
    DocumentRequest document;
    DerivationForm form = DerivationForm::Auto;
    std::vector<std::string> entries;  // as typed: "B11", "C23", "g4"
    bool verify = false;
};

struct FormDocument {
    DerivedDocument derived;
    DerivationForm form = DerivationForm::Expanded;  // Expanded or Structured: the form derived
    Message reason;                                  // why that form (FormAuto, FormAskedFor, …)
    // With verify: one line per comparison ("structured vs numeric core: 3.1e-15 (relative, 3 random states)").
    std::vector<std::string> verification;
    int definitions = 0;  // named quantities of the structured form (0 when not derived)
};

// Throws MessageError naming --entry for a bad entry, InputError for the
// scene's input errors, Cancelled when cancelled.
FormDocument deriveInForm(const Scene& scene, const FormRequest& request);

// The auto rule on its own: whether the expanded form is cheap for this robot, and why.
bool expandedIsCheap(const Scene& scene, Message& reason);

// The form's name for the documents (FormExpanded, FormStructured; nothing for Auto),
// which JSON writes as "expanded", "structured" in English.
Message formName(DerivationForm form);

}  // namespace ll
