#include "core/present/structured_document.hpp"

#include "core/model/one_based.hpp"
#include <algorithm>
#include <chrono>
#include <map>
#include <sstream>
#include <stdexcept>

#include "core/model/cancellation.hpp"
#include "core/present/display_builder.hpp"
#include "core/present/expression_printer.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/present/json_writer.hpp"
#include "core/present/latex_text.hpp"
#include "core/present/localized_document.hpp"
#include "core/present/message_text.hpp"
#include "core/present/structured_notes.hpp"
#include "core/symbolic/index_list.hpp"

namespace ll::present {
namespace {

using symbolic::NamedDefinition;
using symbolic::entryLabel;
using symbolic::lockGinac;

// q1, q2, … (appended: GCC 12 warns falsely, -Wrestrict, on "q" + idx(i) inlined)
std::string coordinateName(int i) {
    std::string name(1, 'q');
    name += idx(i);
    return name;
}

PrintOptions optionsFor(const StructuredDynamics& s, Style style) {
    PrintOptions o;
    o.style = style;
    for (int i = 0; i < s.n; ++i) o.coordinateNames.push_back(coordinateName(i));
    o.trigSymbols = true;
    return o;
}

// Text and LaTeX show the scene's decimals as decimals; JSON's Plain stays exact.
class Printer {
public:
    Printer(const StructuredDynamics& s, Style style) : build_(options(s, style)), style_(displayStyle(style)) {}
    std::string operator()(const GiNaC::ex& e) { return renderDisplay(*build_(e), style_); }

private:
    static DisplayOptions options(const StructuredDynamics& s, Style style) {
        DisplayOptions o = displayOptions(optionsFor(s, style));
        o.readableNumbers = style != Style::Plain;
        return o;
    }
    DisplayBuilder build_;
    DisplayStyle style_;
};

using notes::coordinateList;


// Step headings in LaTeX (text mode with math where the notes have it).
const char* latexStepTitle(int step) {
    switch (step) {
        case 1: return "Kinematic model: the axes $x_f, y_f, z_f$ and origin $o_f$ of every frame $f$, in each link's own frame";
        case 4: return "Jacobian columns $J_{P,j}^{(i)}$ of each centre of mass, in its link's frame ($J_{O,j}^{(i)} = z$ of joint $j$'s axis)";
        case 6: return "Potential energy: $\\gamma_j^{(i)} = g_0^T J_{P,j}^{(i)}$, so $g_j = \\partial E_{\\mathrm{pot}}/\\partial q_j = -\\sum_{i \\ge j} m_i \\gamma_j^{(i)}$";
        case 7: return "Mass matrix: $\\beta_{jk}^{(i)} = m_i J_{P,j}^{(i)T} J_{P,k}^{(i)} + z_j^T I_i z_k$, $b_{jk} = \\sum_{i \\ge \\max(j,k)} \\beta_{jk}^{(i)}$";
        case 8: return "Christoffel symbols: $\\partial b_{jk}/\\partial q_l$ by the Jacobian identities (zero for $l \\le \\min(j,k)$)";
    }
    return "";
}


// Step headings in text (and in LaTeX in another language than English).
Message stepTitle(int step) {
    switch (step) {
        case 1: return MessageId::TitleNamesFrames;
        case 4: return MessageId::TitleNamesJacobians;
        case 6: return MessageId::TitleNamesPotential;
        case 7: return MessageId::TitleNamesMassMatrix;
        case 8: return MessageId::TitleNamesChristoffel;
    }
    return {};
}

const GiNaC::ex& valueOf(const StructuredDynamics& s, const EntryRef& e) {
    return e.matrix == 'B' ? s.B(e.row, e.col) : e.matrix == 'C' ? s.C(e.row, e.col) : s.g(e.row, 0);
}

struct Selection {
    std::vector<EntryRef> entries;  // what to show of B, C, g
    std::vector<bool> definitions;  // which names to show: the ones they need, in the steps asked for
    int needed = 0;                 // how many names all of B, C, g (or the entries asked for) need
    bool checks = false;            // the zero pattern and the skew check (whole model, step 8)
};

bool inSteps(int step, const StructuredDocumentInfo& info) { return step >= info.firstStep && step <= info.lastStep; }

// The entries shown (the ones asked for, else B when step 7 is shown and C, g when step 8
// is) and the names they need: the cone of all of B, C, g, so a name nothing uses (the
// x and y axes of frame 0, when gravity only needs z) is not listed.
Selection select(const StructuredDynamics& s, const StructuredDocumentInfo& info) {
    Selection sel;
    std::vector<EntryRef> all;
    for (int j = 0; j < s.n; ++j)
        for (int k = j; k < s.n; ++k) all.push_back({'B', j, k, entryLabel('B', j, k, s.n)});
    for (int i = 0; i < s.n; ++i)
        for (int j = 0; j < s.n; ++j) all.push_back({'C', i, j, entryLabel('C', i, j, s.n)});
    for (int j = 0; j < s.n; ++j) all.push_back({'g', j, 0, entryLabel('g', j, 0, s.n)});
    const std::vector<EntryRef>& needed = info.entries.empty() ? all : info.entries;
    if (info.entries.empty()) {
        for (const EntryRef& e : all)
            if (inSteps(e.matrix == 'B' ? 7 : 8, info)) sel.entries.push_back(e);
        sel.checks = inSteps(8, info);
    } else {
        sel.entries = info.entries;
    }
    const std::vector<NamedDefinition>& table = s.table->entries();
    std::vector<bool> used(table.size(), false);
    for (const EntryRef& e : needed)
        for (int k : s.table->dependenciesOf(valueOf(s, e))) used[k] = true;
    if (sel.checks)  // the JSON's Ekin and Epot: over the names of B and of step 6
        for (const GiNaC::ex* energy : {&s.Ekin, &s.Epot})
            for (int k : s.table->dependenciesOf(*energy)) used[k] = true;
    for (int k = static_cast<int>(table.size()) - 1; k >= 0; --k)  // dependencies come first in the table
        if (used[k])
            for (int d : table[k].dependencies) used[d] = true;
    sel.definitions.assign(table.size(), false);
    for (std::size_t k = 0; k < table.size(); ++k) {
        sel.needed += used[k] ? 1 : 0;
        sel.definitions[k] = used[k] && inSteps(table[k].step, info);
    }
    return sel;
}

// The selected names grouped by the step where each arises (steps ascending, table order
// within a step: still dependency order, since a name only uses names of its own or
// earlier steps), with a heading for each step.
std::vector<int> byStep(const StructuredDynamics& s, const Selection& sel) {
    std::vector<int> order;
    for (int k = 0; k < s.table->size(); ++k)
        if (sel.definitions[k]) order.push_back(k);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return s.table->entries()[a].step < s.table->entries()[b].step; });
    return order;
}

template <class Heading, class Line>
void forEachDefinition(const StructuredDynamics& s, const Selection& sel, Heading heading, Line line) {
    int step = -1;
    for (int k : byStep(s, sel)) {
        const NamedDefinition& d = s.table->entries()[k];
        if (d.step != step) heading(step = d.step);
        line(d);
    }
}

std::string entryMeaning(const StructuredDynamics& s, const EntryRef& e) {
    const std::string deps = coordinateList(s.table->coordinatesOf(valueOf(s, e)), s.n);
    if (e.matrix == 'B') return "sum of the contributions of " + notes::linkRange(std::max(e.row, e.col), s.n - 1) + "; depends on " + deps;
    if (e.matrix == 'C') {
        const std::string ij = symbolic::indexList({e.row, e.col});
        return "sum_k c_" + ij + (ij.find(',') == std::string::npos ? "k" : ",k") + " qd_k; depends on " + deps + " and the velocities";
    }
    return "depends on " + deps;
}

// entryMeaning in LaTeX: the sum and the coordinates as math.
std::string latexEntryMeaning(const StructuredDynamics& s, const EntryRef& e) {
    const std::string deps = coordinateList(s.table->coordinatesOf(valueOf(s, e)), s.n, notes::Style::Latex);
    if (e.matrix == 'B')
        return "sum of the contributions of " + notes::linkRange(std::max(e.row, e.col), s.n - 1, notes::Style::Latex) + "; depends on " + deps;
    if (e.matrix == 'C')
        return "$\\sum_k c_{" + idx(e.row) + "," + idx(e.col) + ",k}\\,\\dot q_k$; depends on " + deps + " and the velocities";
    return "depends on " + deps;
}

// The zero pattern of ∂b_jk/∂q_l (j ≤ k): one row per (j, k), one column per l.
std::vector<std::string> zeroPattern(const StructuredDynamics& s) {
    std::vector<std::string> rows;
    std::string head = "  jk  ";
    for (int l = 0; l < s.n; ++l) head += " q" + idx(l) + (l + 1 < 9 ? " " : "");
    rows.push_back(head);
    for (int j = 0; j < s.n; ++j)
        for (int k = j; k < s.n; ++k) {
            std::string row = "  " + idx(j) + (s.n >= 10 ? "," : "") + idx(k) + "  ";
            row.resize(6, ' ');
            for (int l = 0; l < s.n; ++l) row += std::string(s.dB[l](j, k).is_zero() ? "  ." : "  x") + (l + 1 < 9 ? " " : "  ");
            rows.push_back(row);
        }
    return rows;
}

void writeText(const StructuredDynamics& s, const StructuredDocumentInfo& info, std::ostream& out) {
    Printer text(s, Style::Text);
    const Selection sel = select(s, info);
    out << s.systemName << "\n" << std::string(s.systemName.size(), '=') << "\n";
    const Language l = info.language;
    out << messageText(MessageId::DocumentForm, l) << ": " << messageText(formName(info.form), l) << " (" << translatedPhrases(info.formReason, l) << ")\n";
    out << "B, C and g are short sums over " << sel.needed
        << " named quantities, each a few operations on earlier names; every vector of link i is written in link i's "
           "own frame, where its centre of mass and inertia tensor are constant.\n";
    forEachDefinition(
        s, sel, [&](int step) { out << "\n" << messageText(MessageId::DocumentStep, l) << " " << step << ". " << messageText(stepTitle(step), l) << "\n"; },
        [&](const NamedDefinition& d) {
            out << "    " << d.name << " = " << text(d.value) << "        ("
                << translatedPhrases(d.meaning.english() + "; depends on " + coordinateList(d.coordinates, s.n), l) << ")\n";
        });
    if (!sel.entries.empty()) out << "\nResults over the names\n";
    for (const EntryRef& e : sel.entries)
        out << "    " << (e.matrix == 'B' ? "b" : e.matrix == 'C' ? "c" : "g") << e.label.substr(1) << " = "
            << text(valueOf(s, e)) << "        (" << translatedPhrases(entryMeaning(s, e), l) << ")\n";
    if (sel.checks)
        out << "    E_kin = 1/2 qd^T B qd        (" << translatedPhrases("the kinetic energy; in JSON written out over the b_jk", l) << ")\n"
            << "    E_pot = " << text(s.Epot) << "        ("
            << translatedPhrases("the potential energy: each link's weight over its gravity and frame-0 names, and the springs", l) << ")\n";
    if (sel.checks) {
        const int n = s.n, total = n * n * (n + 1) / 2;
        out << "\nZero pattern of d b_jk / d q_l (j <= k; x: non-zero): " << s.nonZeroMassDerivatives() << " of " << total
            << " are non-zero\n";
        for (const std::string& row : zeroPattern(s)) out << row << "\n";
        out << "\nSkew symmetry: Bdot - 2C with Bdot = sum_l dB/dq_l qd_l over the same names is "
            << (skewSymmetric(s) ? "skew-symmetric (checked)" : "NOT skew-symmetric") << "\n";
    }
    for (const ExpandedEntry& e : info.expanded)
        out << "\nExpanded " << e.ref.label << " (" << e.terms << " terms, " << e.seconds << " s):\n    " << text(e.value) << "\n";
}

// Each definition is a paragraph of inline math, which TeX breaks after a + or − when
// it is wider than the page (a display would run off it), then its meaning in small
// type with the name as the notes write it.
void writeLatex(const StructuredDynamics& s, const StructuredDocumentInfo& info, std::ostream& out) {
    Printer latex(s, Style::Latex);
    const Selection sel = select(s, info);
    const auto entryName = [&](const EntryRef& e) {
        std::string sub = e.label.substr(1);
        std::replace(sub.begin(), sub.end(), '_', ',');
        return std::string(e.matrix == 'B' ? "b" : e.matrix == 'C' ? "c" : "g") + "_{" + sub + "}";
    };
    out << "\\documentclass[a4paper,10pt]{article}\n"
           "\\usepackage[margin=1.5cm,landscape]{geometry}\n"
           "\\usepackage{amsmath,amssymb}\n"
           "\\allowdisplaybreaks\n"
           "\\setlength{\\parindent}{0pt}\n"
           "\\raggedright\n"
           "\\newcommand{\\lldefinition}[2]{\\par\\hangindent=2em\\hangafter=1 #1\\\\{\\small #2}\\par\\smallskip}\n"
           "\\title{Euler--Lagrange model (structured form): " << latexText(s.systemName) << "}\n"
           "\\author{LagrangeLab}\n\\date{}\n"
           "\\begin{document}\n\\maketitle\n"
        << messageText(MessageId::DocumentForm, info.language) << ": " << messageText(formName(info.form), info.language) << " (" << latexText(translatedPhrases(info.formReason, info.language)) << "). $B$, $C$ and $g$ are short sums over " << sel.needed
        << " named quantities; every vector of link $i$ is written in its own frame. "
           "Shorthand: $c_{i} = \\cos q_i$, $s_{i} = \\sin q_i$.\n";
    forEachDefinition(
        s, sel, [&](int step) {
            out << "\\section*{" << messageText(MessageId::DocumentStep, info.language) << " " << step << "}\n"
                << (info.language == Language::English ? std::string(latexStepTitle(step)) : latexText(messageText(stepTitle(step), info.language)))
                << "\n\\medskip\n";
        },
        [&](const NamedDefinition& d) {
            out << "\\lldefinition{$" << latex(d.symbol) << " = " << latex(d.value) << "$}{$" << d.latex
                << "$: " << latexText(d.meaning.english()) << "; depends on " << coordinateList(d.coordinates, s.n, notes::Style::Latex) << "}\n";
        });
    if (!sel.entries.empty()) out << "\\section*{Results over the names}\n";
    for (const EntryRef& e : sel.entries)
        out << "\\lldefinition{$" << entryName(e) << " = " << latex(valueOf(s, e)) << "$}{"
            << latexEntryMeaning(s, e) << "}\n";
    if (sel.checks)
        out << "\\lldefinition{$E_{\\mathrm{kin}} = \\tfrac{1}{2}\\,\\dot q^{T} B\\,\\dot q$}{the kinetic energy}\n"
            << "\\lldefinition{$E_{\\mathrm{pot}} = " << latex(s.Epot)
            << "$}{the potential energy: each link's weight over its gravity and frame-0 names, and the springs}\n";
    if (sel.checks) {
        const int n = s.n;
        out << "\\paragraph{Zero pattern} " << s.nonZeroMassDerivatives() << " of " << n * n * (n + 1) / 2
            << " derivatives $\\partial b_{jk}/\\partial q_l$ ($j \\le k$) are non-zero. "
            << "$\\dot B - 2C$ is " << (skewSymmetric(s) ? "skew-symmetric (checked over the names)" : "not skew-symmetric") << ".\n";
    }
    for (const ExpandedEntry& e : info.expanded)
        out << "\\paragraph{Expanded $" << entryName(e.ref) << "$} (" << e.terms << " terms)\n\n$" << latex(e.value)
            << "$\n";
    out << "\\end{document}\n";
}

// Written as it is made, in the layout of nlohmann's compact dump() (an 8-joint model
// has about 1100 definitions; building them as a nlohmann document first copied every
// string twice and was a sixth of the printing).
void writeJson(const StructuredDynamics& s, const StructuredDocumentInfo& info, std::ostream& out) {
    Printer plain(s, Style::Plain);
    const Selection sel = select(s, info);
    std::string text;
    JsonWriter j(text, JsonWriter::Layout::Compact);
    j.beginObject();
    j.member("system", s.systemName);
    j.member("mode", info.modeName);
    j.member("form", info.form);
    j.member("form_reason", info.formReason);
    std::vector<std::string> coordinates;
    for (int i = 0; i < s.n; ++i) coordinates.push_back(coordinateName(i));
    j.member("coordinates", coordinates);
    j.key("definitions");
    j.beginArray();
    for (int k : byStep(s, sel)) {
        const NamedDefinition& d = s.table->entries()[k];
        // latex: the name as the notes write it; the right-hand side's LaTeX is expr's
        // (--format latex sets it), written twice it was 40 % of an 8-joint document.
        j.beginObject();
        j.member("name", d.name);
        j.member("expr", plain(d.value));
        j.member("latex", d.latex);
        j.member("step", d.step);
        j.member("meaning", d.meaning.english());
        j.key("depends_on");  // indices k of the q_k it depends on: [2, 3] (a tenth of the document as "q2", "q3")
        j.beginArray();
        for (int q = 0; q < s.n; ++q)
            if (d.coordinates & (std::uint64_t(1) << q)) j.value(q + 1);
        j.endArray();
        j.endObject();
    }
    j.endArray();
    const auto matrix = [&](const char* name, const GiNaC::matrix& m) {
        j.key(name);
        j.beginArray();
        for (unsigned r = 0; r < m.rows(); ++r) {
            if (m.cols() == 1) {
                j.value(plain(m(r, 0)));
                continue;
            }
            j.beginArray();
            for (unsigned c = 0; c < m.cols(); ++c) j.value(plain(m(r, c)));
            j.endArray();
        }
        j.endArray();
    };
    if (info.entries.empty() && inSteps(7, info)) matrix("B", s.B);
    if (sel.checks) {
        matrix("C", s.C);
        matrix("g", s.g);
        matrix("Q", s.Q);
        j.member("Ekin", plain(s.Ekin));
        j.member("Epot", plain(s.Epot));
        const int n = s.n;
        j.key("mass_derivatives");
        j.beginObject();
        j.member("nonzero", s.nonZeroMassDerivatives());
        j.member("of", n * n * (n + 1) / 2);
        j.endObject();
        j.member("skew_symmetric", skewSymmetric(s));
    }
    if (!info.entries.empty()) {
        j.key("entries");
        j.beginObject();
        std::vector<std::string> written;  // an entry asked for twice is one member, as in a JSON object
        for (const EntryRef& e : info.entries) {
            if (std::find(written.begin(), written.end(), e.label) != written.end()) continue;
            written.push_back(e.label);
            j.key(e.label);
            j.beginObject();
            j.member("structured", plain(valueOf(s, e)));
            const ExpandedEntry* expanded = nullptr;
            for (const ExpandedEntry& x : info.expanded)
                if (x.ref.label == e.label) expanded = &x;
            if (expanded) {
                j.member("expr", plain(expanded->value));
                j.member("terms", static_cast<long long>(expanded->terms));
                j.member("seconds", expanded->seconds);
            }
            j.endObject();
        }
        j.endObject();
    }
    j.endObject();
    text += '\n';
    out << text;
}

}  // namespace

std::string structuredDocument(const StructuredDynamics& s, DocumentFormat format, const StructuredDocumentInfo& info) {
    const auto lock = lockGinac();
    std::ostringstream out;
    switch (format) {
        case DocumentFormat::Text: writeText(s, info, out); break;
        case DocumentFormat::Latex: writeLatex(s, info, out); break;
        case DocumentFormat::Json: writeJson(s, info, out); break;
        case DocumentFormat::Display:  // a tree, not a string: structuredDisplayDocument (structured_display.hpp)
            throw std::invalid_argument("structuredDocument: the display form is structuredDisplayDocument's");
    }
    return out.str();
}

}  // namespace ll::present
