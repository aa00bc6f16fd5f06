#include "core/present/structured_display.hpp"

#include <algorithm>
#include <map>
#include <regex>

#include "core/model/cancellation.hpp"
#include "core/present/display_builder.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/present/localized_document.hpp"
#include "core/present/number_style.hpp"
#include "core/present/structured_notes.hpp"
#include "core/present/symbol_names.hpp"
#include "core/symbolic/index_list.hpp"

namespace ll::present {
namespace {

std::string idx(int i) { return std::to_string(i + 1); }

using symbolic::joined;
using symbolic::lockGinac;
using symbolic::NamedDefinition;

// base_{sub}^{(link)}: Text "base" + "sub" + "(link)", LaTeX base_{sub}^{(link)}.
std::shared_ptr<DisplayNode> scripted(const std::string& text, const std::string& latex, const std::string& sub, const std::string& link,
                                      const std::string& plain) {
    auto n = std::make_shared<DisplayNode>();
    n->kind = DisplayKind::Symbol;
    n->name = n->plain = plain;
    n->text = text;
    n->latex = latex;
    n->subText = n->subShown = n->subLatex = sub;
    if (!link.empty()) {
        n->supText = "(" + link + ")";
        n->supLatex = "(" + link + ")";
    }
    return n;
}

// ∂_{q_l} x, the derivative of x by q_l: compact inside products (2.45 ∂_{q4}J_{P3,x}^{(5)} J_{P2,x}^{(5)}).
DisplayPtr derivative(const std::shared_ptr<DisplayNode>& of, const std::string& l, const std::string& plain) {
    auto d = std::make_shared<DisplayNode>();
    d->kind = DisplayKind::Symbol;
    d->text = "∂";
    d->latex = "\\partial";
    d->subText = d->subShown = "q" + l;
    d->subLatex = "q_{" + l + "}";
    auto n = std::make_shared<DisplayNode>();
    n->kind = DisplayKind::Raw;
    n->name = n->plain = plain;
    n->text = renderDisplay(*d, DisplayStyle::Text) + renderDisplay(*of, DisplayStyle::Text);
    n->latex = renderDisplay(*d, DisplayStyle::Latex) + " " + renderDisplay(*of, DisplayStyle::Latex);
    n->children = {d, of};
    return n;
}

// The generated names of structured_dynamics.cpp, read back. Compiled on first use, not
// when the program starts: at namespace scope they were a tenth of every command's start
// (`lagrangelab --version` included).
struct NamePatterns {
    const std::regex frameName{R"(([oxyz])([xyz])(\d+)_(\d+))"}, jacobianName{R"(J([xyz])(\d+)_(\d+))"}, gravityName{R"(g([xyz])0_(\d+))"},
        dJacobianName{R"(D([xyz])(\d+)_(\d+)_(\d+))"}, betaName{R"(beta(\d+)_(\d+)_(\d+))"}, gammaName{R"(gamma(\d+)_(\d+))"},
        deltaName{R"(delta(\d+)_(\d+)_(\d+)_(\d+))"}, dbName{R"(Db(\d+)_(\d+)_(\d+))"};
};
const NamePatterns& namePatterns() {
    static const NamePatterns patterns;
    return patterns;
}

// Frames: the links' own frames, where J_P, o_f and the axes are written.
Message sectionTitle(int step) {
    switch (step) {
        case 1: return MessageId::TitleSectionFrames;
        case 4: return MessageId::TitleSectionJacobians;
        case 6: return MessageId::TitleSectionPotential;
        case 7: return MessageId::TitleSectionMassMatrix;
        case 8: return MessageId::TitleSectionCoriolis;
    }
    return {};
}

// The section's general formula, as the notes write it.
StepFormula sectionFormula(int step, const StructuredDynamics& s) {
    const int n = s.n;
    StepFormula f;
    switch (step) {
        case 1:
            f = stepFormula("«1»", R"(T_i^0 = A_1 A_2 \cdots A_i,\quad {}^{(i)}x_f,\ {}^{(i)}y_f,\ {}^{(i)}z_f,\ {}^{(i)}o_f:\ «1»)",
                            {formulaWords(MessageId::FormulaSectionFrames)},
                            {formulaWords(MessageId::FormulaColumnsOf, {"(T_i^0)^{-1} T_f^0"})});
            break;
        case 4:
            f = stepFormula("«1»",
                            R"(J_{P,j}^{(i)} = z_j \times (p_{ci} - o_j)\ «1»,\quad J_{P,j}^{(i)} = z_j\ «2»,\quad J_{O,j}^{(i)} = z_j)",
                            {formulaWords(MessageId::FormulaJacobianColumns, {"J_P,j^(i) = z_j × (p_ci − o_j)", "z_j"})},
                            {formulaWords(MessageId::FormulaRevolute), formulaWords(MessageId::FormulaPrismatic)});
            break;
        case 6:
            f = stepFormula(
                "«g»_j = −Σ_{i≥j} m_i g0ᵀ J_P,j^(i) «1».",
                R"(\gamma_j^{(i)} = g_0^T J_{P,j}^{(i)},\quad «g»_j = \frac{\partial E_{\mathrm{pot}}}{\partial «q_»j} = -\sum_{i \ge j} m_i\, \gamma_j^{(i)})",
                {formulaWords(MessageId::FormulaForSpring, {"K_j («q_»j − «q_»j,rest)"})});
            break;
        case 7:
            f = stepFormula(
                "«b»_jk = Σ_{i≥max(j,k)} β_jk^(i) «1»; «2»",
                R"(\beta_{jk}^{(i)} = m_i\, J_{P,j}^{(i)T} J_{P,k}^{(i)} + z_j^T I_i\, z_k,\quad «b»_{jk} = \sum_{i \ge \max(j,k)} \beta_{jk}^{(i)})",
                {formulaWords(MessageId::FormulaForMotor, {"J_m G²", "«b»_jj"}),
                 formulaWords(MessageId::FormulaDependsOnOnly, {"«b»_jk", "q_{min(j,k)+1..n}"})});
            break;
        case 8:
            f = stepFormula(
                "c_ij = Σ_k ½ (∂«b»_ij/∂«q_»k + ∂«b»_ik/∂«q_»j − ∂«b»_jk/∂«q_»i) «q'_»k;  «B» q̈ + C q̇ + «g» = «Q».  «1»",
                R"(c_{ij} = \sum_k \tfrac{1}{2}\left(\frac{\partial «b»_{ij}}{\partial «q_»k} + \frac{\partial «b»_{ik}}{\partial «q_»j} - \frac{\partial «b»_{jk}}{\partial «q_»i}\right)«q'_»k,\quad «B»«q''» + C«q'» + «g» = «Q»)",
                {formulaWords(MessageId::FormulaNonZeroDerivatives,
                              {std::to_string(s.nonZeroMassDerivatives()), std::to_string(n * n * (n + 1) / 2), "∂«b»_jk/∂q_l (j ≤ k)"})});
            break;
    }
    return f;
}

using notes::coordinateList;

}  // namespace

DisplayPtr structuredNameNode(const std::string& name) {
    const NamePatterns& p = namePatterns();
    std::smatch m;
    if (std::regex_match(name, m, p.frameName)) return scripted(m[1], m[1], m[3].str() + "," + m[2].str(), m[4], name);
    if (std::regex_match(name, m, p.jacobianName)) return scripted("J", "J", "P" + m[2].str() + "," + m[1].str(), m[3], name);
    if (std::regex_match(name, m, p.gravityName)) return scripted("g", "g", "0," + m[1].str(), m[2], name);
    if (std::regex_match(name, m, p.betaName)) return scripted("β", "\\beta", joined({m[1], m[2]}), m[3], name);
    if (std::regex_match(name, m, p.gammaName)) return scripted("γ", "\\gamma", m[1], m[2], name);
    if (std::regex_match(name, m, p.dJacobianName))
        return derivative(scripted("J", "J", "P" + m[2].str() + "," + m[1].str(), m[3], name), m[4], name);
    if (std::regex_match(name, m, p.deltaName)) return derivative(scripted("β", "\\beta", joined({m[1], m[2]}), m[3], name), m[4], name);
    if (std::regex_match(name, m, p.dbName)) return derivative(scripted("b", "b", joined({m[1], m[2]}), "", name), m[3], name);
    return displaySymbolName(name);
}

std::shared_ptr<const DisplayDocument> structuredDisplayDocument(const StructuredDynamics& s, const Message& formReason, int firstStep,
                                                                 int lastStep, const std::atomic<bool>* cancel) {
    const auto lock = lockGinac();
    auto doc = std::make_shared<DisplayDocument>();
    doc->systemName = s.systemName;
    for (int i = 0; i < s.n; ++i) doc->coordinateNames.push_back("q" + idx(i));
    doc->form = MessageId::FormStructured;
    doc->formReason = formReason;
    doc->actuationNote = MessageId::ActuationDeclaredForces;
    doc->actuation = doc->actuationNote.english();

    auto names = std::make_shared<std::map<std::string, DisplayPtr>>();
    for (const NamedDefinition& d : s.table->entries()) (*names)[d.name] = structuredNameNode(d.name);
    DisplayOptions options;
    options.names = {doc->coordinateNames, true, s.symbolLinks};
    options.givenSymbols = names;
    options.readableNumbers = true;
    DisplayBuilder build(options);

    // The names under the step where each arises (table order within a step is still
    // dependency order: a name only uses names of its own or earlier steps).
    std::map<int, std::vector<int>> byStep;
    for (int k = 0; k < s.table->size(); ++k) byStep[s.table->entries()[k].step].push_back(k);
    const auto shown = [&](int step) { return step >= firstStep && step <= lastStep; };
    const auto item = [&](const std::string& name, Quantity quantity, int row, int col, const DisplayPtr& label, const GiNaC::ex& value,
                          Message note) {
        throwIfCancelled(cancel);  // a newer edit need not wait for this document under the GiNaC lock
        DisplayItem it;
        it.name = name;
        it.latexName = renderDisplay(*label, DisplayStyle::Latex);
        it.quantity = quantity;
        it.row = row;
        it.col = col;
        it.value = build(value);
        it.equation = displayEquation(label, it.value);
        useOneNumberStyle(it);
        it.note = std::move(note);
        return it;
    };
    const auto entryLabel = [&](const char* letter, std::vector<std::string> indices) {
        auto n = std::make_shared<DisplayNode>();
        n->kind = DisplayKind::Symbol;
        n->text = n->latex = letter;
        n->subText = n->subShown = n->subLatex = joined(indices);
        n->name = n->plain = letter + n->subText;
        return DisplayPtr(n);
    };
    for (int step : {1, 4, 6, 7, 8}) {
        const bool hasNames = byStep.count(step) > 0;
        if (!shown(step) || (!hasNames && step != 7 && step != 8)) continue;
        DisplayStep st;
        st.number = step;
        st.title = sectionTitle(step);
        st.general = sectionFormula(step, s);
        writeFormula(st, {});
        if (hasNames)
            for (int k : byStep[step]) {
                const NamedDefinition& d = s.table->entries()[k];
                st.items.push_back(item(d.name, Quantity::NamedQuantity, -1, -1, names->at(d.name), d.value,
                                        message(MessageId::NoteMeaningDependsOn, d.meaning, coordinateList(d.coordinates, s.n))));
            }
        if (step == 7)
            for (int j = 0; j < s.n; ++j)
                for (int k = j; k < s.n; ++k)
                    st.items.push_back(item("b" + joined({idx(j), idx(k)}), Quantity::MassMatrixEntry, j, k,
                                            entryLabel("b", {idx(j), idx(k)}), s.B(j, k),
                                            message(MessageId::NoteMeaningDependsOn, notes::linkRange(std::max(j, k), s.n - 1),
                                                    coordinateList(s.coordinatesOfB(j, k), s.n))));
        if (step == 8) {
            for (int j = 0; j < s.n; ++j)
                st.items.push_back(item("g" + idx(j), Quantity::GravityEntry, j, -1, entryLabel("g", {idx(j)}), s.g(j, 0),
                                        message(MessageId::NoteDependsOn, coordinateList(s.table->coordinatesOf(s.g(j, 0)), s.n))));
            for (int i = 0; i < s.n; ++i)
                for (int j = 0; j < s.n; ++j)
                    st.items.push_back(item("c" + joined({idx(i), idx(j)}), Quantity::CoriolisEntry, i, j,
                                            entryLabel("c", {idx(i), idx(j)}), s.C(i, j), {}));
            for (int j = 0; j < s.n; ++j)
                if (!s.Q(j, 0).is_zero())
                    st.items.push_back(item("Q" + idx(j), Quantity::ForceEntry, j, -1, entryLabel("Q", {idx(j)}), s.Q(j, 0), {}));
        }
        doc->steps.push_back(std::move(st));
    }
    return doc;
}

}  // namespace ll::present
