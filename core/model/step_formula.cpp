#include "core/model/step_formula.hpp"

#include <stdexcept>
#include <utility>

namespace ll {
namespace {

FormulaPiece letterPiece(FormulaLetter letter, unsigned char dots = 0) {
    FormulaPiece p;
    p.kind = FormulaPiece::Kind::Letter;
    p.letter = letter;
    p.dots = dots;
    return p;
}

// The piece a mark's name stands for («B» → the mass matrix's letter).
FormulaPiece marked(std::string_view name, std::vector<FormulaPiece>& inserts) {
    using L = FormulaLetter;
    if (name == "B") return letterPiece(L::MassMatrix);
    if (name == "b") return letterPiece(L::MassEntry);
    if (name == "g") return letterPiece(L::Gravity);
    if (name == "Q") return letterPiece(L::Force);
    if (name == "q") return letterPiece(L::JointVector);
    if (name == "q'") return letterPiece(L::JointVector, 1);
    if (name == "q''") return letterPiece(L::JointVector, 2);
    if (name == "q_") return letterPiece(L::JointVariable);
    if (name == "q'_") return letterPiece(L::JointVariable, 1);
    if (name == "q''_") return letterPiece(L::JointVariable, 2);
    if (name.size() == 1 && name[0] >= '1' && name[0] <= '9' && static_cast<std::size_t>(name[0] - '1') < inserts.size())
        return std::move(inserts[static_cast<std::size_t>(name[0] - '1')]);
    throw std::logic_error("formulaPieces: no mark «" + std::string(name) + "»");
}

}  // namespace

FormulaPieces formulaPieces(std::string_view source, std::vector<FormulaPiece> inserts) {
    static constexpr std::string_view open = "«", close = "»";
    FormulaPieces out;
    const auto math = [&](std::string_view text) {
        if (text.empty()) return;
        FormulaPiece p;
        p.math = std::string(text);
        out.push_back(std::move(p));
    };
    for (std::size_t at = 0;;) {
        const std::size_t begin = source.find(open, at);
        if (begin == std::string_view::npos) {
            math(source.substr(at));
            return out;
        }
        const std::size_t end = source.find(close, begin);
        if (end == std::string_view::npos) throw std::logic_error("formulaPieces: « without » in " + std::string(source));
        math(source.substr(at, begin - at));
        out.push_back(marked(source.substr(begin + open.size(), end - begin - open.size()), inserts));
        at = end + close.size();
    }
}

FormulaPiece formulaMath(std::string math) {
    FormulaPiece p;
    p.math = std::move(math);
    return p;
}

FormulaPiece formulaWordsOf(MessageId id, std::vector<FormulaPieces> args) {
    FormulaPiece p;
    p.kind = FormulaPiece::Kind::Words;
    p.words = id;
    p.args = std::move(args);
    return p;
}

FormulaPiece formulaWords(MessageId id, const std::vector<std::string>& args) {
    std::vector<FormulaPieces> pieces;
    for (const std::string& a : args) pieces.push_back(formulaPieces(a));
    return formulaWordsOf(id, std::move(pieces));
}

StepFormula stepFormula(std::string_view text, std::string_view latex, std::vector<FormulaPiece> textInserts,
                        std::vector<FormulaPiece> latexInserts) {
    return {formulaPieces(text, std::move(textInserts)), formulaPieces(latex, std::move(latexInserts))};
}

FormulaPiece formulaActuation(std::vector<int> actuated, std::vector<std::string> coordinates) {
    FormulaPiece p;
    p.kind = FormulaPiece::Kind::Actuation;
    p.actuated = std::move(actuated);
    p.coordinates = std::move(coordinates);
    return p;
}

}  // namespace ll
