#include "core/present/localized_document.hpp"

#include <utility>

#include "core/model/actuation.hpp"
#include "core/present/labels.hpp"
#include "core/present/latex_formula.hpp"
#include "core/present/latex_text.hpp"
#include "core/present/message_text.hpp"
#include "core/present/step_formula_text.hpp"
#include "core/present/symbol_names.hpp"

namespace ll::present {
namespace {

// A robot's joint variables q_i, q̇_i, q̈_i with the notation's letter (Craig's θ_i) in
// every tree; the nodes not touched are shared.
DisplayPtr renamed(const DisplayPtr& node, const NotationSymbols& n) {
    if (!node) return node;
    if (node->kind == DisplayKind::Symbol && node->text == "q" && !node->subText.empty()) {
        auto copy = std::make_shared<DisplayNode>(*node);
        copy->text = n.coordinate;
        copy->latex = n.coordinateLatex;
        return copy;
    }
    std::shared_ptr<DisplayNode> copy;
    for (std::size_t k = 0; k < node->children.size(); ++k)
        if (DisplayPtr c = renamed(node->children[k], n); c != node->children[k]) {
            if (!copy) copy = std::make_shared<DisplayNode>(*node);
            copy->children[k] = std::move(c);
        }
    for (std::size_t r = 0; r < node->rows.size(); ++r)
        for (std::size_t k = 0; k < node->rows[r].size(); ++k)
            if (DisplayPtr c = renamed(node->rows[r][k], n); c != node->rows[r][k]) {
                if (!copy) copy = std::make_shared<DisplayNode>(*node);
                copy->rows[r][k] = std::move(c);
            }
    return copy ? copy : node;
}

// The item's label in the notation: B(q) → D(q) or M(Θ), g(q) → G(Θ), Q → τ.
void relabel(DisplayItem& item, const NotationSymbols& n, bool robot) {
    const std::string of = "(" + (robot ? n.vectorLatex : std::string("q")) + ")";
    switch (item.quantity) {
        case Quantity::MassMatrix:
            item.name = n.mass;
            item.latexName = n.mass + of;
            item.entryLetter = n.massEntry;
            break;
        case Quantity::GravityVector:
            item.name = n.gravity;
            item.latexName = n.gravity + of;
            item.entryLetter = n.gravity;
            break;
        case Quantity::GeneralizedForces:
            item.name = n.force;
            item.latexName = n.forceLatex;
            item.entryLetter = n.force;
            break;
        default: return;
    }
    item.equation = displayEquation(displayLabel(item.name, item.latexName), item.value);
}

}  // namespace

std::string massMatrixSum(const NotationSymbols& n) {
    return ",\\quad " + n.mass + "(" + n.vectorLatex +
           R"() = \sum_i \left(m_i\, J_{P,i}^T J_{P,i} + J_{O,i}^T R_i\, I_{li}\, R_i^T J_{O,i}\right))";
}

void writeFormula(DisplayStep& step, const FormulaReader& reader) {
    step.formulaText = formulaText(step.general, reader);
    step.formulaLatex = formulaLatex(step.general, reader);
    if (reader.notation == Notation::Craig && step.number == 8 && reader.robot)
        step.formulaLatex += R"(,\quad V(\Theta, \dot{\Theta}) = C\,\dot{\Theta})";
    const bool sumsB = step.number == 7 && reader.robot;
    step.formula = formulaFromLatex(step.formulaLatex + (sumsB ? massMatrixSum(notationSymbols(reader.notation)) : ""), step.formulaText);
}

std::string actuationSentence(const std::vector<int>& actuated, const std::vector<std::string>& coordinates, Language language) {
    return actuationText(actuated, coordinates,
                         {messageText(MessageId::ActuationNoInputs, language), messageText(MessageId::ActuationInputsOn, language),
                          messageText(MessageId::ActuationUnderactuated, language),
                          messageText(MessageId::ActuationFullyActuated, language)});
}

std::shared_ptr<DisplayDocument> localizedDocument(const DisplayDocument& document, const Presentation& p) {
    auto out = std::make_shared<DisplayDocument>(document);
    out->language = p.language;
    out->notation = p.notation;
    const NotationSymbols& n = notationSymbols(p.notation);
    const bool letters = p.notation != Notation::Notes, rename = document.robot && n.coordinate != "q";
    for (DisplayStep& step : out->steps) {
        writeFormula(step, {p.language, p.notation, document.robot});
        for (DisplayItem& item : step.items) {
            if (rename) {
                item.equation = renamed(item.equation, n);
                item.value = renamed(item.value, n);
            }
            if (letters) relabel(item, n, document.robot);
        }
    }
    out->remark = {};
    if (document.robot && letters && n.modifiedDH != document.modifiedDH)
        out->remark = n.modifiedDH ? MessageId::RemarkCraigNeedsModifiedDh : MessageId::RemarkNotationNeedsStandardDh;
    if (!document.actuationFromInputs) {  // a fixed text (the structured form's)
        if (!document.actuationNote.empty()) out->actuation = messageText(document.actuationNote, p.language);
        out->actuationLatex.clear();
        return out;
    }
    // The actuation sentence with the coordinates as the results show them.
    const NameRules rules{document.coordinateNames, document.robot, {}};
    std::vector<std::string> shown, latex, marks;
    for (const std::string& name : document.coordinateNames) {
        const DisplayPtr symbol =
            rename ? renamed(symbolNode(name, symbolMeaning(name, rules), rules), n) : symbolNode(name, symbolMeaning(name, rules), rules);
        shown.push_back(renderDisplay(*symbol, DisplayStyle::Text));
        latex.push_back("$" + renderDisplay(*symbol, DisplayStyle::Latex) + "$");
        marks.push_back("@" + std::to_string(marks.size()) + "@");
    }
    out->actuation = actuationSentence(document.actuated, shown, p.language);
    out->actuationLatex = latexText(actuationSentence(document.actuated, marks, p.language));  // the prose escaped, then the math put in
    for (std::size_t k = marks.size(); k-- > 0;)
        for (std::size_t at; (at = out->actuationLatex.find(marks[k])) != std::string::npos;)
            out->actuationLatex.replace(at, marks[k].size(), latex[k]);
    return out;
}

}  // namespace ll::present
