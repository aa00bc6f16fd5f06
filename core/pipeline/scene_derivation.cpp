#include "core/pipeline/scene_derivation.hpp"

#include <atomic>
#include <chrono>

#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/lagrangian_derivation.hpp"
#include "core/symbolic/robot_derivation.hpp"

namespace ll {

const char* modeName(symbolic::ParameterMode mode) {
    switch (mode) {
        case symbolic::ParameterMode::Numeric: return "numeric";
        case symbolic::ParameterMode::Textbook: return "symbolic";
        case symbolic::ParameterMode::Parametric: break;
    }
    return "parameters";
}

namespace {
std::atomic<long> derivations{0};
}  // namespace

long documentDerivations() { return derivations.load(); }

DerivedDocument deriveDocument(const Scene& scene, const DocumentRequest& request) {
    derivations.fetch_add(1);
    const auto lock = symbolic::lockGinac();
    symbolic::DerivationOptions options;
    options.mode = request.mode;
    options.firstStep = request.firstStep;
    options.lastStep = request.lastStep;
    options.progress = request.progress;
    options.cancel = request.cancel;
    symbolic::Derivation d;
    if (scene.lagrangian) {
        throwIfCancelled(request.cancel);
        d = symbolic::deriveLagrangian(scene, request.mode);
    } else {
        d = symbolic::deriveRobot(scene, options);
    }
    std::erase_if(d.steps, [&](const symbolic::DerivationStep& s) { return s.number < request.firstStep || s.number > request.lastStep; });
    throwIfCancelled(request.cancel);
    DerivedDocument out;
    const auto printing = std::chrono::steady_clock::now();
    if (request.format == present::DocumentFormat::Display) {
        auto display = present::displayDocument(d, request.cancel, request.forPages);
        display->form = request.form.form;
        display->formReason = request.form.reason;
        if (request.catalogue) out.catalogue = expandedCatalogue(scene, d, *display);
        out.display = std::move(display);
    } else {
        out.document = present::derivationDocument(d, request.format, modeName(request.mode), request.form, request.presentation);
    }
    out.printSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - printing).count();
    for (const symbolic::DerivationStep& step : d.steps) out.timings.push_back({step.number, step.title.english(), step.seconds});
    out.warnings = d.warnings;
    return out;
}

}  // namespace ll
