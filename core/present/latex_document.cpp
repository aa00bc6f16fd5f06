#include "core/present/latex_document.hpp"

#include "core/present/latex_text.hpp"

namespace ll::present {

std::string itemLatex(const DisplayItem& item) { return renderDisplay(*item.equation, DisplayStyle::Latex); }

std::string latexDocument(const DisplayDocument& document) {
    std::string out =
        "\\documentclass[a4paper,10pt]{article}\n"
        "\\usepackage[margin=1.5cm,landscape]{geometry}\n"
        "\\usepackage{amsmath,amssymb}\n"
        "\\allowdisplaybreaks\n"
        "\\setcounter{MaxMatrixCols}{20}\n"
        "\\title{" + std::string(document.language == Language::Danish ? "Euler--Lagrange-model" : "Euler--Lagrange model") + ": " + latexText(document.systemName) + "}\n"
        "\\author{LagrangeLab}\n\\date{}\n"
        "\\begin{document}\n\\maketitle\n";
    const Language l = document.language;
    if (!document.form.empty()) out += translated("Form", l) + ": " + document.form + " (" + latexText(document.formReason) + ").\n";
    if (!document.remark.empty()) out += latexText(document.remark) + ".\n";
    out += translated("Shorthand", l) + ": $c_{i} = \\cos q_i$, $s_{i} = \\sin q_i$, $c_{12} = \\cos(q_1 + q_2)$, $\\dot{q}_i$ " +
           translated("the joint velocities", l) + ".\n";
    for (const DisplayStep& step : document.steps) {
        out += "\\section*{" + translated("Step", l) + " " + std::to_string(step.number) + ": " + latexText(step.title) + "}\n\\[ " + step.formulaLatex + " \\]\n";
        for (const DisplayItem& item : step.items) out += "\\[ " + itemLatex(item) + " \\]\n";
    }
    // The coordinates in math ($\theta_{2}$), the rest as text.
    const std::string actuation = document.actuationLatex.empty() ? latexText(document.actuation) : document.actuationLatex;
    return out + "\\paragraph{" + translated("Actuation", l) + "} " + actuation + ".\n\\end{document}\n";
}

}  // namespace ll::present
