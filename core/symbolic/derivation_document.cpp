#include "core/symbolic/derivation_document.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <sstream>

#include "core/model/actuation.hpp"
#include "core/model/cancellation.hpp"
#include "core/symbolic/angle_sums.hpp"
#include "core/symbolic/expression_printer.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/json_writer.hpp"
#include "core/symbolic/latex_formula.hpp"
#include "core/symbolic/latex_text.hpp"
#include "core/symbolic/readable_numbers.hpp"
#include "core/symbolic/trig_context.hpp"

namespace ll::symbolic {
namespace {

// Entries with more terms than this are shown as derived (expanded, in display order),
// without the c_i² → s_i² choice, angle sums, common factors and grouping, whose cost
// grows faster than the entry and which no reader follows at that length anyway.
constexpr std::size_t maxShapedTerms = 300;

template <class T>
using ExMap = std::unordered_map<GiNaC::ex, T, std::hash<GiNaC::ex>, GiNaC::ex_is_equal>;

// The common factor of the terms of an expanded sum, velocities left inside (the
// textbook's −m2 a1 ℓc2 s2 (q̇1 + q̇2), not … q̇2 (…)): the symbols every term has, at
// their least power, with the rational content and a common sign. 1 when none.
GiNaC::ex commonFactor(const GiNaC::ex& e, const std::vector<GiNaC::symbol>& velocities) {
    if (!GiNaC::is_a<GiNaC::add>(e)) return 1;
    std::map<GiNaC::ex, int, GiNaC::ex_is_less> common;
    bool first = true, allNegative = true, rational = true;
    GiNaC::numeric gcdNum = 0, lcmDen = 1;
    for (const GiNaC::ex& term : e) {
        std::map<GiNaC::ex, int, GiNaC::ex_is_less> here;
        GiNaC::numeric coef = 1;
        for (const GiNaC::ex& f : GiNaC::is_a<GiNaC::mul>(term) ? term : GiNaC::ex(GiNaC::lst{term})) {
            if (GiNaC::is_a<GiNaC::numeric>(f)) {
                coef = GiNaC::ex_to<GiNaC::numeric>(f);
            } else if (GiNaC::is_a<GiNaC::symbol>(f)) {
                here[f] = 1;
            } else if (GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::symbol>(f.op(0)) &&
                       f.op(1).info(GiNaC::info_flags::posint)) {
                here[f.op(0)] = GiNaC::ex_to<GiNaC::numeric>(f.op(1)).to_int();
            }
        }
        if (!coef.is_rational()) rational = false;
        if (rational) {
            gcdNum = GiNaC::gcd(gcdNum, coef.numer());
            lcmDen = GiNaC::lcm(lcmDen, coef.denom());
        }
        allNegative = allNegative && coef.is_real() && coef.is_negative();
        if (first) {
            common = here;
            first = false;
        } else {
            for (auto it = common.begin(); it != common.end();) {
                const auto h = here.find(it->first);
                if (h == here.end()) {
                    it = common.erase(it);
                } else {
                    it->second = std::min(it->second, h->second);
                    ++it;
                }
            }
        }
        if (common.empty()) return 1;
    }
    GiNaC::ex factor = 1;
    for (const auto& entry : common) {  // not a structured binding: clang 14 (fuzz build) cannot capture one
        const auto& symbol = entry.first;
        if (std::none_of(velocities.begin(), velocities.end(), [&](const GiNaC::symbol& v) { return symbol.is_equal(v); }))
            factor *= GiNaC::pow(symbol, entry.second);
    }
    if (factor.is_equal(1)) return 1;
    GiNaC::numeric content = rational ? gcdNum / lcmDen : GiNaC::numeric(1);
    if (allNegative) content = -content;
    return content * factor;
}

// How an item reads in a textbook: combined angles (c12), grouped by masses, or by
// velocities for the velocity-linear results (C, ω, v_c); each scalar presented once.
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
        const bool byVelocity =
            name == "C" || name == "E_kin" || name.rfind("w_", 0) == 0 || name.rfind("v_c", 0) == 0;
        ExMap<GiNaC::ex>& cache = cache_[byVelocity ? 1 : 0];
        if (auto it = cache.find(value); it != cache.end()) return it->second;
        // Shaping (sines for cosines, angle sums) costs more than linear time and only
        // pays off on entries a reader can follow: larger ones stay as derived.
        GiNaC::ex e = value.expand();
        if (termCount(e) > maxShapedTerms) return cache.emplace(value, readableNumbers(e)).first->second;
        if (robot_) e = combiner_.combine(shorterInSines(e));
        // Robots group by masses (m2 (a1² + ...)); a hand-typed Lagrangian by its
        // parameters, so the notes' spring term reads K2 (θ1 − θ2).
        const GiNaC::ex common = robot_ ? commonFactor(e, d_.qd) : GiNaC::ex(1);
        if (!common.is_equal(1)) e = (e / common).expand();
        std::vector<GiNaC::symbol> groupBy = byVelocity ? d_.qd : robot_ ? massSymbols(e) : parameters();
        const GiNaC::ex shown = common * readableNumbers(collectForDisplay(e, groupBy));
        return cache.emplace(value, shown).first->second;
    }

    // Row i of B q̈ + C q̇ + g = Q in that order: b_i1 q̈1 + … + (C q̇)_i + g_i, the
    // velocity part as one sum over the velocity products with its common factor out
    // (the 2R's −m2 a1 ℓc2 s2 (2 q̇1 q̇2 + q̇2²)).
    std::vector<GiNaC::ex> equationParts(int i) {
        std::vector<GiNaC::ex> parts;
        for (size_t j = 0; j < d_.q.size(); ++j) parts.push_back(present("B", d_.B(i, j)) * d_.qdd[j]);
        GiNaC::ex velocity = 0;
        size_t terms = 0;  // counted on the entries: expanding a long row first costs more than all the rest
        for (size_t j = 0; j < d_.q.size(); ++j) {
            velocity += d_.C(i, j) * d_.qd[j];
            terms += termCount(d_.C(i, j));
        }
        if (terms <= maxShapedTerms) {
            parts.push_back(present("C", velocity));
        } else {  // too long to factor: entry by entry, each already presented for C
            for (size_t j = 0; j < d_.q.size(); ++j) parts.push_back(present("C", d_.C(i, j)) * d_.qd[j]);
        }
        parts.push_back(present("g", d_.g(i, 0)));
        return parts;
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

    const Derivation& d_;
    bool robot_;
    AngleSumCombiner combiner_;
    ExMap<GiNaC::ex> cache_[2];  // by velocity grouping
};

// B, C, g, Q, E_kin, E_pot as displayed (JSON's top level), whatever steps are shown.
struct DisplayResults {
    DisplayPtr B, C, g, Q, Ekin, Epot;
};

DisplayItem displayItem(const DerivationItem& item, Presenter& presenter, DisplayBuilder& build,
                        const DisplayOptions& options) {
    DisplayItem out{item.name, item.latexName, nullptr, nullptr, {}};
    if (item.name.rfind("equation_", 0) == 0) {
        const int row = std::stoi(item.name.substr(9)) - 1;
        std::vector<DisplayPtr> parts;
        for (const GiNaC::ex& part : presenter.equationParts(row))
            if (!part.is_zero()) parts.push_back(build(part));
        out.value = build(presenter.present("Q", item.value.rhs()));
        out.equation = displayEquation(displaySumOf(parts), out.value);
        return out;
    }
    out.value = build(presenter.present(item.name, item.value));
    out.equation = displayEquation(displayLabel(item.name, item.latexName, options), out.value);
    return out;
}

// The name of entry (r, c) of a matrix item: b11 for B, g2 for g, T_2^0[1,4] otherwise.
std::string entryName(const std::string& name, std::size_t r, std::size_t c, bool column) {
    const std::string rc = column ? std::to_string(r + 1) : std::to_string(r + 1) + std::to_string(c + 1);
    if (name.size() == 1 && std::isalpha(static_cast<unsigned char>(name[0])))
        return std::string(1, static_cast<char>(std::tolower(static_cast<unsigned char>(name[0])))) + rc;
    return name + "[" + (column ? std::to_string(r + 1) : std::to_string(r + 1) + "," + std::to_string(c + 1)) + "]";
}

// Text columns of the longest line.
std::size_t widestLine(const std::string& s) {
    std::size_t widest = 0, n = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const unsigned char b = static_cast<unsigned char>(s[i]);
        if (b == '\n') {
            widest = std::max(widest, n);
            n = 0;
        } else if ((b & 0xC0) != 0x80 && !(b == 0xCC || (b == 0xCD && i + 1 < s.size() && static_cast<unsigned char>(s[i + 1]) < 0xB0))) {
            ++n;
        }
    }
    return std::max(widest, n);
}

std::string itemLatex(const DisplayItem& item) { return renderDisplay(*item.equation, DisplayStyle::Latex); }

// A value's Plain in JSON: a matrix as rows of entries (a column as a list).
void writePlain(JsonWriter& json, const DisplayNode& value) {
    if (value.kind != DisplayKind::Matrix) return json.value(renderDisplay(value, DisplayStyle::Plain));
    json.beginArray();
    for (const auto& r : value.rows) {
        if (r.size() == 1) {
            json.value(renderDisplay(*r[0], DisplayStyle::Plain));
            continue;
        }
        json.beginArray();
        for (const DisplayPtr& c : r) json.value(renderDisplay(*c, DisplayStyle::Plain));
        json.endArray();
    }
    json.endArray();
}

// The documents in parts: head, each step's start, each item, tail.

void writeTextHead(const std::string& systemName, std::ostream& out) {
    out << systemName << "\n" << std::string(systemName.size(), '=') << "\n";
}

void writeTextStep(const DisplayStep& step, std::ostream& out) {
    out << "\nStep " << step.number << ". " << step.title << "\n    " << step.formulaText << "\n\n";
}

void writeTextItem(const std::string& text, std::ostream& out) { out << text << "\n\n"; }

void writeTextTail(const std::string& actuation, std::ostream& out) { out << "Actuation: " << actuation << "\n"; }

void writeLatexHead(const std::string& systemName, std::ostream& out) {
    out << "\\documentclass[a4paper,10pt]{article}\n"
           "\\usepackage[margin=1.5cm,landscape]{geometry}\n"
           "\\usepackage{amsmath,amssymb}\n"
           "\\allowdisplaybreaks\n"
           "\\setcounter{MaxMatrixCols}{20}\n"
           "\\title{Euler--Lagrange model: " << latexText(systemName) << "}\n"
           "\\author{LagrangeLab}\n\\date{}\n"
           "\\begin{document}\n\\maketitle\n"
           "Shorthand: $c_{i} = \\cos q_i$, $s_{i} = \\sin q_i$, $c_{12} = \\cos(q_1 + q_2)$, $\\dot{q}_i$ the joint velocities.\n";
}

void writeLatexStep(const DisplayStep& step, std::ostream& out) {
    out << "\\section*{Step " << step.number << ": " << latexText(step.title) << "}\n\\[ " << step.formulaLatex << " \\]\n";
}

void writeLatexItem(const std::string& latex, std::ostream& out) { out << "\\[ " << latex << " \\]\n"; }

void writeLatexTail(const std::string& actuation, std::ostream& out) {
    out << "\\paragraph{Actuation} " << latexText(actuation) << ".\n"
        << "\\end{document}\n";
}

// The text and LaTeX documents' parts, by format. An item comes as its one rendering.
struct StreamWriters {
    void (*head)(const std::string& systemName, std::ostream& out);
    void (*step)(const DisplayStep& step, std::ostream& out);  // the step's start: its items follow
    void (*item)(const std::string& rendering, std::ostream& out);
    void (*tail)(const std::string& actuation, std::ostream& out);
};

StreamWriters streamWriters(DocumentFormat format) {
    if (format == DocumentFormat::Latex) return {writeLatexHead, writeLatexStep, writeLatexItem, writeLatexTail};
    return {writeTextHead, writeTextStep, writeTextItem, writeTextTail};
}

void writeJsonHead(const Derivation& d, const std::string& mode, JsonWriter& json) {
    json.beginObject();
    json.member("system", d.systemName);
    json.member("mode", mode);
    json.member("coordinates", d.coordinateNames);
    json.key("steps");
    json.beginArray();
}

// A step's start: its number, title, formula and time; its items follow.
void writeJsonStep(const DisplayStep& step, JsonWriter& json) {
    json.beginObject();
    json.member("number", step.number);
    json.member("title", step.title);
    json.key("formula");
    json.beginObject();
    json.member("text", step.formulaText);
    json.member("latex", step.formulaLatex);
    json.endObject();
    json.member("seconds", step.seconds);
    json.key("items");
    json.beginArray();
}

void endJsonStep(JsonWriter& json) {
    json.endArray();
    json.endObject();
}

// An item: its name, LaTeX, Text and re-parsable Plain (`expr`).
void writeJsonItem(const DisplayItem& item, JsonWriter& json) {
    json.beginObject();
    json.member("name", item.name);
    json.member("latex", itemLatex(item));
    json.member("text", itemText(item));
    json.key("expr");
    if (item.name.rfind("equation_", 0) == 0)
        json.value(renderDisplay(*item.equation, DisplayStyle::Plain));
    else
        writePlain(json, *item.value);
    json.endObject();
}

void writeJsonTail(const Derivation& d, const DisplayResults& results, JsonWriter& json) {
    json.endArray();
    for (const auto& [name, value] : {std::pair{"B", &results.B}, {"C", &results.C}, {"g", &results.g}, {"Q", &results.Q},
                                      {"Ekin", &results.Ekin}, {"Epot", &results.Epot}}) {
        json.key(name);
        writePlain(json, **value);
    }
    std::vector<std::string> actuated;
    for (int a : d.actuated) actuated.push_back(d.coordinateNames[a]);
    json.member("actuated", actuated);
    json.member("underactuated", d.underactuated);
    json.member("warnings", d.warnings);
    json.endObject();
}

const char* const massMatrixFormula =
    R"(,\quad B(q) = \sum_i \left(m_i\, J_{P,i}^T J_{P,i} + J_{O,i}^T R_i\, I_{li}\, R_i^T J_{O,i}\right))";

// A step as displayed, without its items yet.
DisplayStep stepHead(const Derivation& d, const DerivationStep& step) {
    DisplayStep s{step.number, step.title, step.formulaText, step.formulaLatex, {}, step.seconds, {}};
    // The notes' general formula typeset; a robot's step 7 also gives B as the notes sum it.
    const bool robot = d.trigToFunctions.nops() > 0;
    s.formula = formulaFromLatex(step.formulaLatex + (robot && step.number == 7 ? massMatrixFormula : ""), step.formulaText);
    return s;
}

// The display document, item by item.
std::shared_ptr<DisplayDocument> shapeDocument(const Derivation& d, Presenter& presenter, DisplayBuilder& build,
                                               const DisplayOptions& options, const std::atomic<bool>* cancel) {
    auto doc = std::make_shared<DisplayDocument>();
    doc->systemName = d.systemName;
    doc->coordinateNames = d.coordinateNames;
    doc->actuation = actuationText(d.actuated, d.coordinateNames);
    for (const DerivationStep& step : d.steps) {
        DisplayStep& shown = doc->steps.emplace_back(stepHead(d, step));
        for (const DerivationItem& item : step.items) {
            throwIfCancelled(cancel);  // a newer edit need not wait for this document under the GiNaC lock
            shown.items.push_back(displayItem(item, presenter, build, options));
        }
    }
    return doc;
}

void writeJson(const Derivation& d, const DisplayDocument& doc, const DisplayResults& results, const std::string& modeName,
               std::string& out) {
    JsonWriter json(out);
    writeJsonHead(d, modeName, json);
    for (const DisplayStep& step : doc.steps) {
        writeJsonStep(step, json);
        for (const DisplayItem& item : step.items) writeJsonItem(item, json);
        endJsonStep(json);
    }
    writeJsonTail(d, results, json);
    out += '\n';
}

}  // namespace

namespace {

// A lower bound of the columns a node takes in Text, counted no further than `limit`:
// every symbol or number at least one column, " + " between terms, a space between
// factors, parentheses around a fence.
std::size_t textColumnsAtLeast(const DisplayNode& n, std::size_t limit) {
    std::size_t count = 0;
    auto add = [&](std::size_t k) { count = std::min(limit, count + k); };
    switch (n.kind) {
    case DisplayKind::Sum:
    case DisplayKind::Product:
        for (std::size_t i = 0; i < n.children.size() && count < limit; ++i)
            add(textColumnsAtLeast(*n.children[i], limit - count) + (i ? (n.kind == DisplayKind::Sum ? 3 : 1) : 0));
        return count;
    case DisplayKind::Fence: return std::min(limit, textColumnsAtLeast(*n.children[0], limit) + 2);
    default: return 1;
    }
}

}  // namespace

std::string itemText(const DisplayItem& item) {
    // A block whose entry alone is wider than a row may be is listed entry by entry
    // without being written as a block first (the expanded Panda's C: megabytes).
    bool tooWide = false;
    if (item.value->kind == DisplayKind::Matrix)
        for (const auto& row : item.value->rows)
            for (const DisplayPtr& cell : row)
                tooWide = tooWide || textColumnsAtLeast(*cell, maxTextMatrixRow + 1) > maxTextMatrixRow;
    if (!tooWide) {
        std::string whole = renderDisplay(*item.equation, DisplayStyle::Text);
        if (item.value->kind != DisplayKind::Matrix || widestLine(whole) <= maxTextMatrixRow) return whole;
    }
    // Too wide to read as a block: the entries one by one, under the matrix's name.
    const auto& rows = item.value->rows;
    const bool column = !rows.empty() && rows[0].size() == 1;
    const bool zeros = hasZeroEntry(*item.value);  // left out, and said so
    std::string out = item.name + " (" + std::to_string(rows.size()) + "×" +
                      std::to_string(rows.empty() ? 0 : rows[0].size()) + "), entry by entry" + (zeros ? ", the zeros left out:" : ":");
    for (std::size_t r = 0; r < rows.size(); ++r)
        for (std::size_t c = 0; c < rows[r].size(); ++c)
            if (!isZeroNumber(*rows[r][c]))
                out += "\n  " + entryName(item.name, r, c, column) + " = " + renderDisplay(*rows[r][c], DisplayStyle::Text);
    return out;
}

std::shared_ptr<const DisplayDocument> displayDocument(const Derivation& d, const std::atomic<bool>* cancel, bool forPages) {
    const auto lock = lockGinac();
    DisplayOptions options = displayOptions(printOptionsFor(d, Style::Text));
    options.cutLongSums = forPages;
    DisplayBuilder build(options);
    Presenter presenter(d, d.trigToFunctions.nops() > 0);
    return shapeDocument(d, presenter, build, options, cancel);
}

std::string renderDocument(const DisplayDocument& document, DocumentFormat format) {
    if (format != DocumentFormat::Text && format != DocumentFormat::Latex) return {};
    std::ostringstream out;
    const StreamWriters write = streamWriters(format);
    write.head(document.systemName, out);
    for (const DisplayStep& step : document.steps) {
        write.step(step, out);
        for (const DisplayItem& item : step.items) write.item(format == DocumentFormat::Latex ? itemLatex(item) : itemText(item), out);
    }
    write.tail(document.actuation, out);
    return out.str();
}

std::string derivationDocument(const Derivation& d, DocumentFormat format, const std::string& modeName) {
    if (format == DocumentFormat::Display) return {};
    const auto lock = lockGinac();
    const DisplayOptions options = displayOptions(printOptionsFor(d, Style::Text));
    DisplayBuilder build(options);
    Presenter presenter(d, d.trigToFunctions.nops() > 0);
    const std::shared_ptr<const DisplayDocument> doc = shapeDocument(d, presenter, build, options, nullptr);
    if (format != DocumentFormat::Json) return renderDocument(*doc, format);
    const auto shown = [&](const char* name, const GiNaC::ex& value) { return build(presenter.present(name, value)); };
    const DisplayResults results{shown("B", d.B), shown("C", d.C), shown("g", d.g),
                                 shown("Q", d.Q), shown("E_kin", d.Ekin), shown("E_pot", d.Epot)};
    std::string out;
    writeJson(d, *doc, results, modeName, out);
    return out;
}

}  // namespace ll::symbolic
