#pragma once
// A scene's derivation as display trees in the form `derive --form` would pick (auto:
// expanded when cheap, else structured; derivation_forms.hpp), for everything that
// typesets: `derive --format pdf|svg|png` and the window's DerivationView. The document
// says which form and why (DisplayDocument::form, formReason). A hand-typed Lagrangian
// keeps its own (expanded) path. Thread-safe like deriveDocument; cancellable.
#include "core/pipeline/derivation_forms.hpp"

namespace ll {

// request.format is ignored (always Display). Throws InputError, Cancelled.
DerivedDocument deriveDisplay(const Scene& scene, const DocumentRequest& request, DerivationForm form = DerivationForm::Auto);

}  // namespace ll
