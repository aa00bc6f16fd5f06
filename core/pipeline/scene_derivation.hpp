#pragma once
// A scene's derivation as a finished document, for callers on any thread (the CLI's
// `derive`, the window's derivation worker): derives (robot or hand-typed Lagrangian)
// and renders under the GiNaC lock, and hands back plain data only. Cancellable
// between entries; progress names the step and entry being derived.
#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/model/cancellation.hpp"
#include "core/model/scene.hpp"
#include "core/pipeline/entry_catalogue.hpp"
#include "core/present/derivation_document.hpp"
#include "core/symbolic/symbolic_robot.hpp"

namespace ll {

struct DocumentRequest {
    symbolic::ParameterMode mode = symbolic::ParameterMode::Parametric;
    int firstStep = 0, lastStep = symbolic::lastDerivationStep;  // the steps shown; B, C, g, Q are always derived
    present::DocumentFormat format = present::DocumentFormat::Text;
    std::function<void(int step, const std::string& what)> progress;  // optional, on the deriving thread
    const std::atomic<bool>* cancel = nullptr;                        // optional: throws Cancelled
    // for format Display: the trees are for pages only (the CLI's pdf, svg, png), so sums
    // longer than pages show are built already cut (present::DisplayOptions::cutLongSums)
    bool forPages = false;
    // the form the document says it is (derivation_forms.hpp, display_derivation.hpp)
    present::FormNote form;
    // for format Display: also trace and compile the entries the document shows, for
    // picking them (entry_catalogue.hpp)
    bool catalogue = false;
    // for formats Text, Latex and Json: the language and notation written (Display gives
    // the trees as derived; their readers apply it with present::localizedDocument)
    present::Presentation presentation;
};

struct StepTiming {
    int number = 0;
    std::string title;
    double seconds = 0.0;
};

struct DerivedDocument {
    std::string document;                                     // in the requested format (empty for Display)
    std::shared_ptr<const present::DisplayDocument> display;  // for format Display: the trees
    std::vector<StepTiming> timings;                          // of the shown steps
    double printSeconds = 0.0;                                // shaping and rendering the document
    std::vector<std::string> warnings;
    std::shared_ptr<const EntryCatalogue> catalogue;  // when asked for (request.catalogue)
};

// "parameters", "numeric" or "symbolic" (the CLI's names, recorded in JSON).
const char* modeName(symbolic::ParameterMode mode);

// Throws InputError for a Lagrangian's input errors and Cancelled when cancelled.
DerivedDocument deriveDocument(const Scene& scene, const DocumentRequest& request);

// How many times this process has called deriveDocument (any thread): what a window
// test counts to check that one edit costs one derivation.
long documentDerivations();

}  // namespace ll
