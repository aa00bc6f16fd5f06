#pragma once
// A derivation (core/symbolic/derivation.hpp) as it reads, decided once for every front
// end: each item in its textbook form (textbook_form.hpp), built as display trees
// (display_builder.hpp) with its label (labels.hpp); then written as text, LaTeX or JSON
// (text_document, latex_document, json_document), or handed on as the trees for the
// typeset pages and the window. Takes the GiNaC lock; the caller must hold it too while
// it owns the Derivation.
#include <atomic>
#include <memory>
#include <string>

#include "core/present/display_document.hpp"
#include "core/present/localized_document.hpp"
#include "core/symbolic/derivation.hpp"

namespace ll::present {

// The derivation's display trees. Throws Cancelled between items once `cancel` is set.
// forPages: long sums built already cut as pages show them (DisplayOptions::cutLongSums).
std::shared_ptr<DisplayDocument> displayDocument(const symbolic::Derivation& derivation, const std::atomic<bool>* cancel = nullptr,
                                                 bool forPages = false);

// Which form was derived (FormExpanded, FormStructured) and why (FormAuto: "auto: 2
// joints: …"), said by the documents when given; empty: not said.
struct FormNote {
    Message form, reason;
};

// The derivation in Text, Latex or Json (Display gives ""), in the presentation's language
// and notation; modeName ("parameters", "numeric", "symbolic") is recorded in the JSON.
std::string derivationDocument(const symbolic::Derivation& derivation, DocumentFormat format, const std::string& modeName,
                               const FormNote& form = {}, const Presentation& presentation = {});

// One step of `derivation` as display trees, its symbols named as `options` say beside the
// derivation's own rules (the structured form's control law: b_jk, c_ij, g_i as given
// nodes). The caller holds the GiNaC lock.
DisplayStep displayStep(const symbolic::Derivation& derivation, const symbolic::DerivationStep& step,
                        std::shared_ptr<const std::map<std::string, DisplayPtr>> givenSymbols);

// A document in Text or Latex from its display trees (no GiNaC: any thread).
std::string renderDocument(const DisplayDocument& document, DocumentFormat format);

}  // namespace ll::present
