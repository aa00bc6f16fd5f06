#include "core/present/derivation_document.hpp"

#include "core/model/cancellation.hpp"
#include "core/present/display_builder.hpp"
#include "core/present/json_document.hpp"
#include "core/present/labels.hpp"
#include "core/present/latex_document.hpp"
#include "core/present/latex_formula.hpp"
#include "core/present/latex_text.hpp"
#include "core/present/localized_document.hpp"
#include "core/present/number_style.hpp"
#include "core/present/text_document.hpp"
#include "core/present/textbook_form.hpp"
#include "core/symbolic/ginac_lock.hpp"

namespace ll::present {
namespace {

using symbolic::Derivation;
using symbolic::DerivationItem;
using symbolic::DerivationStep;

DisplayOptions optionsFor(const Derivation& d, bool forPages) {
    DisplayOptions o;
    o.names.coordinateNames = d.coordinateNames;
    if (o.names.coordinateNames.empty())
        for (const GiNaC::symbol& q : d.q) o.names.coordinateNames.push_back(q.get_name());
    o.names.trigSymbols = d.system == symbolic::SystemKind::Robot;
    o.names.links = d.symbolLinks;
    o.cutLongSums = forPages;
    o.readableNumbers = true;
    o.typedDecimals = d.typedDecimals;
    return o;
}

DisplayItem displayItem(const Derivation& d, const DerivationItem& item, TextbookForm& form, DisplayBuilder& build) {
    DisplayItem out;
    out.name = item.name;
    out.latexName = itemLatexName(item, d);
    out.quantity = item.quantity;
    out.row = item.index;
    if (item.quantity == Quantity::EquationOfMotion) {
        std::vector<DisplayPtr> parts;
        for (const GiNaC::ex& part : form.equationParts(item.index))
            if (!part.is_zero()) parts.push_back(build(part));
        out.value = build(form(item.value.rhs(), form.plainGrouping()));
        out.equation = displayEquation(displaySumOf(parts), out.value);
        useOneNumberStyle(out);
        return out;
    }
    if (!item.parts.empty()) {  // a sum as the derivation wrote it, each part grouped on its own
        std::vector<DisplayPtr> parts;
        const auto inParentheses = [](DisplayPtr x) {
            return displayPrecedence(*x) < 1 ? displayNode(DisplayKind::Fence, {std::move(x)}) : x;  // a sum
        };
        for (const symbolic::ItemPart& part : item.parts) {
            const GiNaC::ex coefficient = form(part.coefficient, part.grouping);
            if (coefficient.is_zero() || part.factor.is_zero()) continue;
            if (!GiNaC::is_a<GiNaC::add>(part.factor) || GiNaC::is_a<GiNaC::numeric>(coefficient)) {  // a number multiplies out
                parts.push_back(build(coefficient * part.factor));
                continue;
            }
            // a sum times a sum: built apart, as GiNaC would pull a common number out of both
            const DisplayPtr c = build(coefficient), f = inParentheses(build(part.factor));
            const bool negated = c->kind == DisplayKind::Sum && c->children.size() == 1 && c->negative[0];
            const DisplayPtr product = displayNode(DisplayKind::Product, {inParentheses(negated ? c->children[0] : c), f});
            parts.push_back(negated ? displayNegated(product) : product);
        }
        const DisplayPtr sum = parts.empty() ? build(GiNaC::ex(0)) : displaySumOf(parts);
        const bool equation = GiNaC::is_a<GiNaC::relational>(item.value);
        out.value = equation ? build(form(item.value.rhs(), item.grouping)) : sum;
        out.equation = displayEquation(equation ? sum : displayLabel(out.name, out.latexName), out.value);
        useOneNumberStyle(out);
        return out;
    }
    if (item.quantity == Quantity::Lagrangian && (d.Ekin - d.Epot - item.value).expand().is_zero()) {
        // as the notes write it, L = E_kin − E_pot: the kinetic terms first
        std::vector<DisplayPtr> parts;
        for (const GiNaC::ex& part : {d.Ekin, GiNaC::ex(-d.Epot)})
            if (!part.is_zero()) parts.push_back(build(form(part, item.grouping)));
        out.value = parts.empty() ? build(GiNaC::ex(0)) : displaySumOf(parts);
    } else {
        out.value = build(form(item.value, item.grouping));
    }
    out.equation = displayEquation(displayLabel(out.name, out.latexName), out.value);
    useOneNumberStyle(out);
    return out;
}

// A step as displayed, without its items yet: the notes' general formula typeset; a
// robot's step 7 also gives B as the notes sum it.
DisplayStep stepHead(const Derivation& d, const DerivationStep& step) {
    DisplayStep s;
    s.number = step.number;
    s.title = step.title;
    s.general = step.formula;
    s.seconds = step.seconds;
    writeFormula(s, {Language::English, Notation::Notes, d.system == symbolic::SystemKind::Robot});
    return s;
}

std::shared_ptr<DisplayDocument> shapeDocument(const Derivation& d, TextbookForm& form, DisplayBuilder& build,
                                               const std::atomic<bool>* cancel) {
    auto doc = std::make_shared<DisplayDocument>();
    doc->systemName = d.systemName;
    doc->coordinateNames = d.coordinateNames;
    doc->actuated = d.actuated;
    doc->actuationFromInputs = true;
    doc->robot = d.system == symbolic::SystemKind::Robot;
    doc->modifiedDH = d.modifiedDH;
    for (const DerivationStep& step : d.steps) {
        DisplayStep& shown = doc->steps.emplace_back(stepHead(d, step));
        for (const DerivationItem& item : step.items) {
            throwIfCancelled(cancel);  // a newer edit need not wait for this document under the GiNaC lock
            shown.items.push_back(displayItem(d, item, form, build));
        }
    }
    return localizedDocument(*doc, {});  // English, the notes' notation: the actuation sentence
}

}  // namespace

std::shared_ptr<DisplayDocument> displayDocument(const Derivation& d, const std::atomic<bool>* cancel, bool forPages) {
    const auto lock = symbolic::lockGinac();
    DisplayBuilder build(optionsFor(d, forPages));
    TextbookForm form(d);
    return shapeDocument(d, form, build, cancel);
}

DisplayStep displayStep(const Derivation& d, const DerivationStep& step, std::shared_ptr<const std::map<std::string, DisplayPtr>> givenSymbols) {
    DisplayOptions options = optionsFor(d, false);
    options.givenSymbols = std::move(givenSymbols);
    DisplayBuilder build(options);
    TextbookForm form(d);
    DisplayStep shown = stepHead(d, step);
    for (const DerivationItem& item : step.items) shown.items.push_back(displayItem(d, item, form, build));
    return shown;
}

std::string renderDocument(const DisplayDocument& document, DocumentFormat format) {
    if (format == DocumentFormat::Text) return textDocument(document);
    if (format == DocumentFormat::Latex) return latexDocument(document);
    return {};
}

std::string derivationDocument(const Derivation& d, DocumentFormat format, const std::string& modeName, const FormNote& note,
                               const Presentation& presentation) {
    if (format == DocumentFormat::Display) return {};
    const auto lock = symbolic::lockGinac();
    DisplayBuilder build(optionsFor(d, false));
    TextbookForm form(d);
    std::shared_ptr<DisplayDocument> doc = shapeDocument(d, form, build, nullptr);
    doc->form = note.form;
    doc->formReason = note.reason;
    doc = localizedDocument(*doc, presentation);
    if (format != DocumentFormat::Json) return renderDocument(*doc, format);
    const auto shown = [&](const GiNaC::ex& value, symbolic::Grouping grouping) { return build(form(value, grouping)); };
    ModelSummary model;
    model.mode = modeName;
    model.B = shown(d.B, form.plainGrouping());
    model.C = shown(d.C, symbolic::Grouping::Velocities);
    model.g = shown(d.g, form.plainGrouping());
    model.Q = shown(d.Q, form.plainGrouping());
    model.Ekin = shown(d.Ekin, symbolic::Grouping::Velocities);
    model.Epot = shown(d.Epot, form.plainGrouping());
    for (int a : d.actuated) model.actuated.push_back(d.coordinateNames[a]);
    model.underactuated = d.underactuated;
    model.warnings = d.warnings;
    return jsonDocument(*doc, model);
}

}  // namespace ll::present
