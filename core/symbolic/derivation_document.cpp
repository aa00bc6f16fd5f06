#include "core/symbolic/derivation_document.hpp"

#include <sstream>

#include <nlohmann/json.hpp>

#include "core/model/actuation.hpp"
#include "core/symbolic/angle_sums.hpp"
#include "core/symbolic/expression_printer.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/readable_numbers.hpp"
#include "core/symbolic/trig_context.hpp"

namespace ll::symbolic {
namespace {

// How an item reads in a textbook: combined angles (c12), grouped by masses, or by
// velocities for the velocity-linear results (C, ω, v_c).
class Presenter {
public:
    Presenter(const Derivation& d, bool robot) : d_(d), robot_(robot), combiner_(d.q) {}

    GiNaC::ex present(const std::string& name, const GiNaC::ex& value) {
        if (GiNaC::is_a<GiNaC::matrix>(value)) {
            GiNaC::matrix m = GiNaC::ex_to<GiNaC::matrix>(value);
            for (unsigned r = 0; r < m.rows(); ++r)
                for (unsigned c = 0; c < m.cols(); ++c) m(r, c) = present(name, m(r, c));
            return m;
        }
        GiNaC::ex e = robot_ ? combiner_.combine(shorterInSines(value)) : value.expand();
        const bool byVelocity =
            name == "C" || name == "E_kin" || name.rfind("w_", 0) == 0 || name.rfind("v_c", 0) == 0;
        // Robots group by masses (m2 (a1² + ...)); a hand-typed Lagrangian by its
        // parameters, so the notes' spring term reads K2 (θ1 − θ2).
        std::vector<GiNaC::symbol> groupBy = byVelocity ? d_.qd : robot_ ? massSymbols(e) : parameters();
        return readableNumbers(collectForDisplay(e, groupBy));
    }

    // Row i of B q̈ + C q̇ + g = Q in that order, each coefficient presented on its own:
    // b_i1 q̈1 + … + c_i1 q̇1 + … + g_i.
    std::vector<GiNaC::ex> equationParts(int i) {
        GiNaC::ex inertial = 0, velocity = 0;
        for (size_t j = 0; j < d_.q.size(); ++j) {
            inertial += present("B", d_.B(i, j)) * d_.qdd[j];
            velocity += present("C", d_.C(i, j)) * d_.qd[j];
        }
        return {inertial, velocity, present("g", d_.g(i, 0))};
    }

private:
    static size_t termCount(const GiNaC::ex& e) { return GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1; }

    // The derivation keeps powers of c_i and reduces s_i² = 1 − c_i² (a canonical form);
    // a textbook writes I1 s1², not I1 − I1 c1². For display, eliminate c_i² instead
    // wherever that gives fewer terms.
    GiNaC::ex shorterInSines(const GiNaC::ex& value) const {
        using namespace GiNaC;  // is_ex_the_function is a macro naming GiNaC's function classes
        ex e = value.expand();
        const GiNaC::lst& trig = d_.trigToFunctions;  // c_i == cos(q_i), s_i == sin(q_i), in pairs
        for (size_t k = 0; k + 1 < trig.nops(); k += 2) {
            const GiNaC::ex c = trig.op(k).lhs(), s = trig.op(k + 1).lhs();
            if (!is_ex_the_function(trig.op(k).rhs(), cos) || e.degree(c) < 2) continue;
            const GiNaC::ex alternative = reducePythagorean(e, c, s);
            if (termCount(alternative) < termCount(e)) e = alternative;
        }
        return e;
    }

    std::vector<GiNaC::symbol> parameters() const {
        std::vector<GiNaC::symbol> symbols;
        for (const GiNaC::ex& rel : d_.parameterValues)
            if (GiNaC::is_a<GiNaC::symbol>(rel.lhs())) symbols.push_back(GiNaC::ex_to<GiNaC::symbol>(rel.lhs()));
        return symbols;
    }

public:

private:
    const Derivation& d_;
    bool robot_;
    AngleSumCombiner combiner_;
};

// Printed parts joined as a sum in the given order ("a + b − c"), zeros left out.
std::string joinTerms(const std::vector<GiNaC::ex>& parts, const PrintOptions& options) {
    std::string out;
    for (const GiNaC::ex& part : parts) {
        if (part.is_zero()) continue;
        std::string text = print(part, options);
        for (const std::string minus : {"\u2212", "-"})
            if (!out.empty() && text.rfind(minus, 0) == 0) {
                out += " " + minus + " " + text.substr(minus.size());
                text.clear();
                break;
            }
        if (!text.empty()) out += (out.empty() ? "" : " + ") + text;
    }
    return out.empty() ? "0" : out;
}

std::string renderItem(const DerivationItem& item, Presenter& presenter, const PrintOptions& options, bool latexName) {
    const std::string name = latexName ? item.latexName : item.name;
    if (item.name.rfind("equation_", 0) == 0) {
        const int row = std::stoi(item.name.substr(9)) - 1;
        return joinTerms(presenter.equationParts(row), options) + " = " + print(presenter.present("Q", item.value.rhs()), options);
    }
    return printEquation(name, presenter.present(item.name, item.value), options);
}

nlohmann::json plainJson(const GiNaC::ex& value, const PrintOptions& plain) {
    if (GiNaC::is_a<GiNaC::matrix>(value)) {
        const GiNaC::matrix& m = GiNaC::ex_to<GiNaC::matrix>(value);
        nlohmann::json rows = nlohmann::json::array();
        for (unsigned r = 0; r < m.rows(); ++r) {
            if (m.cols() == 1) {
                rows.push_back(print(m(r, 0), plain));
                continue;
            }
            nlohmann::json row = nlohmann::json::array();
            for (unsigned c = 0; c < m.cols(); ++c) row.push_back(print(m(r, c), plain));
            rows.push_back(row);
        }
        return rows;
    }
    if (GiNaC::is_a<GiNaC::relational>(value)) return print(value.lhs(), plain) + " = " + print(value.rhs(), plain);
    return print(value, plain);
}

// Plain text for a LaTeX paragraph: < and _ would print as ¡ or start a subscript.
std::string latexText(const std::string& text) {
    std::string out;
    for (char c : text) out += c == '<' ? "$<$" : c == '_' ? "\\_" : std::string(1, c);
    return out;
}

void writeText(const Derivation& d, std::ostream& out) {
    const PrintOptions text = printOptionsFor(d, Style::Text);
    Presenter presenter(d, d.trigToFunctions.nops() > 0);
    out << d.systemName << "\n" << std::string(d.systemName.size(), '=') << "\n";
    for (const DerivationStep& step : d.steps) {
        out << "\nStep " << step.number << ". " << step.title << "\n    " << step.formulaText << "\n\n";
        for (const DerivationItem& item : step.items) out << renderItem(item, presenter, text, false) << "\n\n";
    }
    out << "Actuation: " << actuationText(d.actuated, d.coordinateNames) << "\n";
}

void writeLatex(const Derivation& d, std::ostream& out) {
    const PrintOptions latex = printOptionsFor(d, Style::Latex);
    Presenter presenter(d, d.trigToFunctions.nops() > 0);
    out << "\\documentclass[a4paper,10pt]{article}\n"
           "\\usepackage[margin=1.5cm,landscape]{geometry}\n"
           "\\usepackage{amsmath,amssymb}\n"
           "\\allowdisplaybreaks\n"
           "\\setcounter{MaxMatrixCols}{20}\n"
           "\\title{Euler--Lagrange model: " << d.systemName << "}\n"
           "\\author{LagrangeLab}\n\\date{}\n"
           "\\begin{document}\n\\maketitle\n"
           "Shorthand: $c_{i} = \\cos q_i$, $s_{i} = \\sin q_i$, $c_{12} = \\cos(q_1 + q_2)$, $\\dot{q}_i$ the joint velocities.\n";
    for (const DerivationStep& step : d.steps) {
        out << "\\section*{Step " << step.number << ": " << step.title << "}\n\\[ " << step.formulaLatex << " \\]\n";
        for (const DerivationItem& item : step.items) out << "\\[ " << renderItem(item, presenter, latex, true) << " \\]\n";
    }
    out << "\\paragraph{Actuation} " << latexText(actuationText(d.actuated, d.coordinateNames)) << ".\n"
        << "\\end{document}\n";
}

void writeJson(const Derivation& d, const std::string& mode, std::ostream& out) {
    const PrintOptions text = printOptionsFor(d, Style::Text), latex = printOptionsFor(d, Style::Latex),
                       plain = printOptionsFor(d, Style::Plain);
    Presenter presenter(d, d.trigToFunctions.nops() > 0);
    nlohmann::ordered_json j;
    j["system"] = d.systemName;
    j["mode"] = mode;
    j["coordinates"] = d.coordinateNames;
    nlohmann::ordered_json steps = nlohmann::ordered_json::array();
    for (const DerivationStep& step : d.steps) {
        nlohmann::ordered_json s;
        s["number"] = step.number;
        s["title"] = step.title;
        s["formula"] = {{"text", step.formulaText}, {"latex", step.formulaLatex}};
        s["seconds"] = step.seconds;
        nlohmann::ordered_json items = nlohmann::ordered_json::array();
        for (const DerivationItem& item : step.items) {
            nlohmann::ordered_json it;
            it["name"] = item.name;
            it["latex"] = renderItem(item, presenter, latex, true);
            it["text"] = renderItem(item, presenter, text, false);
            it["expr"] = plainJson(item.value, plain);
            items.push_back(it);
        }
        s["items"] = items;
        steps.push_back(s);
    }
    j["steps"] = steps;
    j["B"] = plainJson(d.B, plain);
    j["C"] = plainJson(d.C, plain);
    j["g"] = plainJson(d.g, plain);
    j["Q"] = plainJson(d.Q, plain);
    j["Ekin"] = print(d.Ekin, plain);
    j["Epot"] = print(d.Epot, plain);
    std::vector<std::string> actuated;
    for (int a : d.actuated) actuated.push_back(d.coordinateNames[a]);
    j["actuated"] = actuated;
    j["underactuated"] = d.underactuated;
    j["warnings"] = d.warnings;
    out << j.dump(2) << '\n';
}

}  // namespace

std::string derivationDocument(const Derivation& d, DocumentFormat format, const std::string& modeName) {
    const auto lock = lockGinac();
    std::ostringstream out;
    switch (format) {
        case DocumentFormat::Text: writeText(d, out); break;
        case DocumentFormat::Latex: writeLatex(d, out); break;
        case DocumentFormat::Json: writeJson(d, modeName, out); break;
    }
    return out.str();
}

}  // namespace ll::symbolic
