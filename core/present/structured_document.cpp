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
#include "core/present/message_text.hpp"
#include "core/present/structured_notes.hpp"
#include "core/symbolic/index_list.hpp"

namespace ll::present {
namespace {

using symbolic::entryLabel;
using symbolic::lockGinac;
using symbolic::NamedDefinition;

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

// Step headings in LaTeX: their words are LaTeX, with math where the notes have it.
Message latexStepTitle(int step) {
    switch (step) {
        case 1: return MessageId::TitleNamesFramesLatex;
        case 4: return MessageId::TitleNamesJacobiansLatex;
        case 6: return MessageId::TitleNamesPotentialLatex;
        case 7: return MessageId::TitleNamesMassMatrixLatex;
        case 8: return MessageId::TitleNamesChristoffelLatex;
    }
    return {};
}

// Step headings in text.
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
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return s.table->entries()[a].step < s.table->entries()[b].step; });
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

// What an entry is: its sum and the coordinates it depends on (in LaTeX as math).
Message entryMeaning(const StructuredDynamics& s, const EntryRef& e, notes::Style style) {
    const Message deps = coordinateList(s.table->coordinatesOf(valueOf(s, e)), s.n, style);
    if (e.matrix == 'B')
        return message(MessageId::NoteContributionsDependsOn, notes::linkRange(std::max(e.row, e.col), s.n - 1, style), deps);
    if (e.matrix == 'C') {
        const std::string ij = symbolic::indexList({e.row, e.col});
        return message(MessageId::NoteDependsOnAndVelocities,
                       style == notes::Style::Latex ? "$\\sum_k c_{" + idx(e.row) + "," + idx(e.col) + ",k}\\,\\dot q_k$"
                                                    : "sum_k c_" + ij + (ij.find(',') == std::string::npos ? "k" : ",k") + " qd_k",
                       deps);
    }
    return message(MessageId::NoteDependsOn, deps);
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
    out << messageText(MessageId::DocumentForm, l) << ": " << messageText(info.form, l) << " (" << messageText(info.formReason, l) << ")\n";
    out << messageText(message(MessageId::StructuredSummary, sel.needed), l) << "\n";
    forEachDefinition(
        s, sel,
        [&](int step) {
            out << "\n" << messageText(MessageId::DocumentStep, l) << " " << step << ". " << messageText(stepTitle(step), l) << "\n";
        },
        [&](const NamedDefinition& d) {
            out << "    " << d.name << " = " << text(d.value) << "        ("
                << messageText(message(MessageId::NoteMeaningDependsOn, d.meaning, coordinateList(d.coordinates, s.n)), l) << ")\n";
        });
    if (!sel.entries.empty()) out << "\n" << messageText(MessageId::StructuredResults, l) << "\n";
    for (const EntryRef& e : sel.entries)
        out << "    "
            << (e.matrix == 'B'   ? "b"
                : e.matrix == 'C' ? "c"
                                  : "g")
            << e.label.substr(1) << " = " << text(valueOf(s, e)) << "        (" << messageText(entryMeaning(s, e, notes::Style::Text), l)
            << ")\n";
    if (sel.checks)
        out << "    E_kin = 1/2 qd^T B qd        (" << messageText(MessageId::NoteKineticEnergyInJson, l) << ")\n"
            << "    E_pot = " << text(s.Epot) << "        (" << messageText(MessageId::NotePotentialEnergy, l) << ")\n";
    if (sel.checks) {
        const int n = s.n, total = n * n * (n + 1) / 2;
        out << "\n" << messageText(message(MessageId::StructuredZeroPattern, s.nonZeroMassDerivatives(), total), l) << "\n";
        for (const std::string& row : zeroPattern(s)) out << row << "\n";
        out << "\n"
            << messageText(skewSymmetric(s) ? MessageId::StructuredSkewSymmetric : MessageId::StructuredNotSkewSymmetric, l) << "\n";
    }
    for (const ExpandedEntry& e : info.expanded)
        out << "\n"
            << messageText(message(MessageId::StructuredExpanded, e.ref.label), l) << " ("
            << messageText(message(MessageId::StructuredTerms, e.terms), l) << ", " << e.seconds << " s):\n    " << text(e.value) << "\n";
}

// Each definition is a paragraph of inline math, which TeX breaks after a + or − when
// it is wider than the page (a display would run off it), then its meaning in small
// type with the name as the notes write it.
void writeLatex(const StructuredDynamics& s, const StructuredDocumentInfo& info, std::ostream& out) {
    Printer latex(s, Style::Latex);
    const Selection sel = select(s, info);
    const Language l = info.language;
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
           "\\title{"
        << messageText(message(MessageId::LatexStructuredTitle, latexText(s.systemName)), l)
        << "}\n"
           "\\author{LagrangeLab}\n\\date{}\n"
           "\\begin{document}\n\\maketitle\n"
        << messageText(MessageId::DocumentForm, l) << ": " << messageText(info.form, l) << " ("
        << latexText(messageText(info.formReason, l)) << "). " << messageText(message(MessageId::LatexStructuredSummary, sel.needed), l)
        << " " << latexMessageText(MessageId::DocumentShorthand, l) << ": $c_{i} = \\cos q_i$, $s_{i} = \\sin q_i$.\n";
    forEachDefinition(
        s, sel,
        [&](int step) {
            out << "\\section*{" << messageText(MessageId::DocumentStep, l) << " " << step << "}\n"
                << messageText(latexStepTitle(step), l) << "\n\\medskip\n";
        },
        [&](const NamedDefinition& d) {
            out << "\\lldefinition{$" << latex(d.symbol) << " = " << latex(d.value) << "$}{$" << d.latex << "$: "
                << latexMessageText(message(MessageId::NoteMeaningDependsOn, latexText(messageText(d.meaning, l)),
                                            coordinateList(d.coordinates, s.n, notes::Style::Latex)),
                                    l)
                << "}\n";
        });
    if (!sel.entries.empty()) out << "\\section*{" << latexMessageText(MessageId::StructuredResults, l) << "}\n";
    for (const EntryRef& e : sel.entries)
        out << "\\lldefinition{$" << entryName(e) << " = " << latex(valueOf(s, e)) << "$}{"
            << latexMessageText(entryMeaning(s, e, notes::Style::Latex), l) << "}\n";
    if (sel.checks)
        out << "\\lldefinition{$E_{\\mathrm{kin}} = \\tfrac{1}{2}\\,\\dot q^{T} B\\,\\dot q$}{"
            << latexMessageText(MessageId::NoteKineticEnergy, l) << "}\n"
            << "\\lldefinition{$E_{\\mathrm{pot}} = " << latex(s.Epot) << "$}{" << latexMessageText(MessageId::NotePotentialEnergy, l)
            << "}\n";
    if (sel.checks) {
        const int n = s.n;
        out << "\\paragraph{" << latexMessageText(MessageId::StructuredZeroPatternHeading, l) << "} "
            << messageText(message(MessageId::LatexNonZeroDerivatives, s.nonZeroMassDerivatives(), n * n * (n + 1) / 2), l) << " "
            << messageText(skewSymmetric(s) ? MessageId::LatexSkewSymmetric : MessageId::LatexNotSkewSymmetric, l) << "\n";
    }
    for (const ExpandedEntry& e : info.expanded)
        out << "\\paragraph{" << latexMessageText(message(MessageId::StructuredExpanded, "$" + entryName(e.ref) + "$"), l) << "} ("
            << latexMessageText(message(MessageId::StructuredTerms, e.terms), l) << ")\n\n$" << latex(e.value) << "$\n";
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
    j.member("form", messageText(info.form, info.language));
    j.member("form_reason", messageText(info.formReason, info.language));
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
        j.member("meaning", messageText(d.meaning, info.language));
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
