#include "core/present/step_formula_text.hpp"

#include <vector>

#include "core/present/latex_text.hpp"
#include "core/present/localized_document.hpp"
#include "core/present/message_text.hpp"

namespace ll::present {
namespace {

enum class Spelling { Unicode, Latex };

struct Writer {
    const NotationSymbols& n;
    const FormulaReader& reader;
    Spelling style;

    std::string letter(const FormulaPiece& p) const {
        const bool renamed = reader.robot && n.coordinate != "q";
        std::string base;
        switch (p.letter) {
            case FormulaLetter::MassMatrix: return n.mass;
            case FormulaLetter::MassEntry: return n.massEntry;
            case FormulaLetter::Gravity: return n.gravity;
            case FormulaLetter::Force:
                return style == Spelling::Latex ? n.forceLatex : n.force;
            case FormulaLetter::JointVector:
                base = style == Spelling::Latex ? (reader.robot ? n.vectorLatex : "q") : !renamed ? "q" : "Θ";
                break;
            case FormulaLetter::JointVariable:
                base = style == Spelling::Latex ? (reader.robot ? n.coordinateLatex : "q") : !renamed ? "q" : n.coordinate;
                break;
        }
        if (style == Spelling::Latex && p.dots > 0) base = (p.dots == 1 ? "\\dot{" : "\\ddot{") + base + "}";
        if (style == Spelling::Unicode && p.dots > 0) base += p.dots == 1 ? "\u0307" : "\u0308";  // combining dot(s) above
        return p.letter == FormulaLetter::JointVariable ? base + "_" : base;
    }

    // The words with their arguments; in LaTeX the words in text mode and the arguments as
    // math between them, a space kept on the side where the words have one:
    // "(rotor {1} turns at {2})" → \text{(rotor } j \text{ turns at } G_j \dot{q}_j\text{)}.
    std::string words(const FormulaPiece& p) const {
        if (style != Spelling::Latex) {
            Message m(p.words);
            for (const FormulaPieces& a : p.args) m.args.push_back(literal(write(a)));
            return messageText(m, reader.language);
        }
        const std::string source = wordsOf(p.words, reader.language);
        std::vector<std::string> segments(1);  // the words around the arguments …
        std::vector<std::size_t> between;      // … and which argument stands after segments[k]
        for (std::size_t at = 0; at < source.size(); ++at) {
            const std::size_t k = at + 2 < source.size() && source[at] == '{' && source[at + 2] == '}'
                                      ? static_cast<std::size_t>(source[at + 1] - '1')
                                      : p.args.size();
            if (k >= p.args.size()) {
                segments.back() += source[at];
                continue;
            }
            between.push_back(k);
            segments.emplace_back();
            at += 2;
        }
        std::string out;
        for (std::size_t s = 0; s < segments.size(); ++s) {
            const std::string& words = segments[s];
            if (!words.empty()) out += (s > 0 && words.front() == ' ' ? " \\text{" : "\\text{") + latexText(words) + "}";
            if (s < between.size()) out += (!words.empty() && words.back() == ' ' ? " " : "") + write(p.args[between[s]]);
        }
        return out;
    }

    std::string write(const FormulaPieces& pieces) const {
        std::string out;
        for (const FormulaPiece& p : pieces) switch (p.kind) {
                case FormulaPiece::Kind::Math: out += p.math; break;
                case FormulaPiece::Kind::Letter: out += letter(p); break;
                case FormulaPiece::Kind::Words: out += words(p); break;
                case FormulaPiece::Kind::Actuation: {
                    const std::string sentence = actuationSentence(p.actuated, p.coordinates, reader.language);
                    out += style == Spelling::Latex ? "\\text{" + latexText(sentence) + "}" : sentence;
                    break;
                }
            }
        return out;
    }
};

}  // namespace

std::string formulaText(const StepFormula& formula, const FormulaReader& reader) {
    return Writer{notationSymbols(reader.notation), reader, Spelling::Unicode}.write(formula.text);
}

std::string formulaLatex(const StepFormula& formula, const FormulaReader& reader) {
    return Writer{notationSymbols(reader.notation), reader, Spelling::Latex}.write(formula.latex);
}

}  // namespace ll::present
