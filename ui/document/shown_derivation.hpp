#pragma once
// A derivation as the window shows it: the worker's (English, the notes' notation) in the
// language and notation chosen, with the answers an exercise asks for hidden
// (core/present/hidden_answers), its text made again from the trees shown. The worker's
// own result when nothing changes.
#include <memory>
#include <vector>

#include "core/present/hidden_answers.hpp"
#include "core/present/localized_document.hpp"
#include "ui/document/live_derivation.hpp"

namespace ll::ui {

std::shared_ptr<const DerivationResult> shownDerivation(std::shared_ptr<const DerivationResult> derived,
                                                        const present::Presentation& presentation,
                                                        const std::vector<present::EntryPlace>& hidden);

}  // namespace ll::ui
