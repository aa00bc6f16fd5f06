#include "ui/document/shown_derivation.hpp"

#include "core/present/text_document.hpp"

namespace ll::ui {

std::shared_ptr<const DerivationResult> shownDerivation(std::shared_ptr<const DerivationResult> derived,
                                                        const present::Presentation& presentation,
                                                        const std::vector<present::EntryPlace>& hidden) {
    const bool localized = presentation.language != present::Language::English || presentation.notation != present::Notation::Notes;
    if (!derived->display || (!localized && hidden.empty())) return derived;
    auto shown = std::make_shared<DerivationResult>(*derived);
    if (localized) shown->display = present::localizedDocument(*derived->display, presentation);
    if (!hidden.empty()) shown->display = std::make_shared<present::DisplayDocument>(present::withAnswersHidden(*shown->display, hidden));
    shown->textSpans.clear();
    shown->text = QString::fromStdString(present::textDocument(*shown->display, &shown->textSpans));
    return shown;
}

}  // namespace ll::ui
