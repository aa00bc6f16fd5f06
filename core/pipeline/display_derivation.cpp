#include "core/pipeline/display_derivation.hpp"

#include <chrono>

#include "core/symbolic/ginac_lock.hpp"
#include "core/present/structured_control_law.hpp"
#include "core/present/structured_display.hpp"

namespace ll {
namespace {

DerivedDocument deriveInForm(const Scene& scene, const DocumentRequest& request, bool expanded, const Message& reason) {
    using namespace symbolic;
    using namespace present;
    DerivedDocument out;
    if (expanded) {
        DocumentRequest display = request;
        display.format = DocumentFormat::Display;
        display.form = {MessageId::FormExpanded, reason};
        return deriveDocument(scene, display);
    }
    const auto lock = lockGinac();
    DerivationOptions options;
    options.mode = request.mode;
    options.progress = request.progress;
    options.cancel = request.cancel;
    const StructuredDynamics s = deriveStructured(scene, options);
    throwIfCancelled(request.cancel);
    const auto printing = std::chrono::steady_clock::now();
    out.display = structuredDisplayDocument(s, reason, request.firstStep, request.lastStep, request.cancel);
    if (scene.effects.control && request.firstStep <= controlStepNumber && request.lastStep >= controlStepNumber) {
        auto withLaw = std::make_shared<DisplayDocument>(*out.display);
        withLaw->steps.push_back(structuredControlStep(scene, s));  // over step 8's entries by name
        out.display = std::move(withLaw);
    }
    out.printSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - printing).count();
    if (request.catalogue) out.catalogue = structuredCatalogue(scene, s, *out.display);
    out.timings.push_back({0, "structured derivation (steps 1-8)", s.seconds});
    return out;
}

}  // namespace

DerivedDocument deriveDisplay(const Scene& scene, const DocumentRequest& request, DerivationForm form) {
    Message reason;
    const bool cheap = scene.lagrangian || expandedIsCheap(scene, reason);
    if (scene.lagrangian) reason = MessageId::FormTypedLagrangian;
    else reason = form == DerivationForm::Auto ? message(MessageId::FormAuto, reason) : Message(MessageId::FormAskedFor);
    const bool expanded = scene.lagrangian || form == DerivationForm::Expanded || (form == DerivationForm::Auto && cheap);
    return deriveInForm(scene, request, expanded, reason);
}

}  // namespace ll
