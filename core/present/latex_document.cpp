#include "core/present/latex_document.hpp"

#include "core/present/latex_text.hpp"
#include "core/present/message_text.hpp"

namespace ll::present {
namespace {

// Words in LaTeX's text mode with their en dashes as TeX writes them (Euler--Lagrange).
std::string withTexDashes(std::string words) {
    for (std::size_t at; (at = words.find("–")) != std::string::npos;) words.replace(at, std::string("–").size(), "--");
    return words;
}

}  // namespace

std::string itemLatex(const DisplayItem& item) { return renderDisplay(*item.equation, DisplayStyle::Latex); }

std::string latexDocument(const DisplayDocument& document) {
    std::string out = "\\documentclass[a4paper,10pt]{article}\n"
                      "\\usepackage[margin=1.5cm,landscape]{geometry}\n"
                      "\\usepackage{amsmath,amssymb}\n"
                      "\\allowdisplaybreaks\n"
                      "\\setcounter{MaxMatrixCols}{20}\n"
                      "\\title{" +
                      withTexDashes(messageText(MessageId::DocumentModelTitle, document.language)) + ": " + latexText(document.systemName) +
                      "}\n"
                      "\\author{LagrangeLab}\n\\date{}\n"
                      "\\begin{document}\n\\maketitle\n";
    const Language l = document.language;
    if (!document.form.empty())
        out += messageText(MessageId::DocumentForm, l) + ": " + messageText(document.form, l) + " (" +
               latexText(messageText(document.formReason, l)) + ").\n";
    if (!document.remark.empty()) out += latexText(messageText(document.remark, l)) + ".\n";
    out += messageText(MessageId::DocumentShorthand, l) +
           ": $c_{i} = \\cos q_i$, $s_{i} = \\sin q_i$, $c_{12} = \\cos(q_1 + q_2)$, $\\dot{q}_i$ " +
           messageText(MessageId::DocumentJointVelocities, l) + ".\n";
    for (const DisplayStep& step : document.steps) {
        out += "\\section*{" + messageText(MessageId::DocumentStep, l) + " " + std::to_string(step.number) + ": " +
               latexText(messageText(step.title, l)) + "}\n\\[ " + step.formulaLatex + " \\]\n";
        for (const DisplayItem& item : step.items) out += "\\[ " + itemLatex(item) + " \\]\n";
    }
    // The coordinates in math ($\theta_{2}$), the rest as text.
    const std::string actuation = document.actuationLatex.empty() ? latexText(document.actuation) : document.actuationLatex;
    return out + "\\paragraph{" + messageText(MessageId::DocumentActuation, l) + "} " + actuation + ".\n\\end{document}\n";
}

}  // namespace ll::present
