#include "core/present/notation.hpp"

namespace ll::present {

std::optional<Notation> notationNamed(std::string_view name) {
    if (name == "notes") return Notation::Notes;
    if (name == "siciliano") return Notation::Siciliano;
    if (name == "spong") return Notation::Spong;
    if (name == "craig") return Notation::Craig;
    return std::nullopt;
}

const char* notationName(Notation notation) {
    switch (notation) {
        case Notation::Siciliano: return "siciliano";
        case Notation::Spong: return "spong";
        case Notation::Craig: return "craig";
        default: return "notes";
    }
}

const NotationSymbols& notationSymbols(Notation notation) {
    static const NotationSymbols notes{"B", "b", "g", "Q", "Q", "q", "q", "q", false};
    static const NotationSymbols siciliano{"B", "b", "g", "τ", "\\tau", "q", "q", "q", false};
    static const NotationSymbols spong{"D", "d", "g", "τ", "\\tau", "q", "q", "q", false};
    static const NotationSymbols craig{"M", "m", "G", "τ", "\\tau", "θ", "\\theta", "\\Theta", true};
    switch (notation) {
        case Notation::Siciliano: return siciliano;
        case Notation::Spong: return spong;
        case Notation::Craig: return craig;
        default: return notes;
    }
}

}  // namespace ll::present
