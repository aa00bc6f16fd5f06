#include "core/present/labels.hpp"

#include <cctype>
#include <memory>

#include "core/present/symbol_names.hpp"

namespace ll::present {
namespace {

using symbolic::Quantity;

// A symbol's name in LaTeX as it reads inside the expressions (theta1 → \theta_{1},
// x_cart_dot → \dot{x}_{\mathrm{cart}}), the user's names taken as they are.
std::string latexOfSymbol(const std::string& name) {
    const NameRules rules{{}, false, {}};
    return renderDisplay(*symbolNode(name, symbolMeaning(name, rules), rules), DisplayStyle::Latex);
}

// The content of the braces that open at `at` ({...}) or the one character there,
// advancing `at` past them.
std::string braced(const std::string& s, std::size_t& at) {
    if (at >= s.size() || s[at] != '{') return at < s.size() ? std::string(1, s[at++]) : std::string();
    int depth = 0;
    const std::size_t start = at + 1;
    for (; at < s.size(); ++at) {
        depth += s[at] == '{' ? 1 : s[at] == '}' ? -1 : 0;
        if (depth == 0) break;
    }
    return s.substr(start, at++ - start);
}

// \dot{q} → q̇, \mathcal{L} → ℒ, \omega → ω, \mathrm{kin} → kin.
std::string shownLabelPart(std::string latex) {
    for (const auto& [from, to] : {std::pair<std::string, std::string>{"\\mathcal{L}", "ℒ"}, {"\\partial ", "∂"}})
        for (std::size_t at; (at = latex.find(from)) != std::string::npos;) latex.replace(at, from.size(), to);
    for (const std::string accent : {"\\dot{", "\\ddot{"}) {
        for (std::size_t at; (at = latex.find(accent)) != std::string::npos;) {
            std::size_t open = at + accent.size() - 1;
            std::string shown = shownFromLatex(braced(latex, open));
            std::size_t first = 1;
            while (first < shown.size() && (static_cast<unsigned char>(shown[first]) & 0xC0) == 0x80) ++first;
            shown = shown.substr(0, first) + (accent == "\\ddot{" ? "\u0308" : "\u0307") + shown.substr(first);
            latex.replace(at, open - at, shown);
        }
    }
    return shownFromLatex(latex);
}

// The letter a matrix's entries are named with (b for B; d for Spong's D, set by the
// notation), or empty when its entries take the matrix's own name with their indices.
std::string entryLetter(const DisplayItem& item) {
    if (!item.entryLetter.empty()) return item.entryLetter;
    switch (item.quantity) {
        case Quantity::MassMatrix: return "b";
        case Quantity::CoriolisMatrix: return "c";
        case Quantity::GravityVector: return "g";
        case Quantity::GeneralizedForces: return "Q";
        case Quantity::Coordinates: return "q";
        default: return {};
    }
}

// A fraction label on one line as the notes write it inline: \frac{\partial \mathcal{L}}{\partial \dot{\theta}_{1}}
// → ∂L/∂θ̇1, \frac{d}{dt}\frac{…}{…} → d/dt ∂L/∂θ̇1.
std::string inlineFractions(const std::string& latex) {
    std::string out;
    for (std::size_t at = 0; at < latex.size();) {
        if (latex.compare(at, 5, "\\frac") == 0) {
            at += 5;
            const std::string top = braced(latex, at), bottom = braced(latex, at);
            if (!out.empty() && out.back() != ' ') out += ' ';
            out += shownLabelPart(top) + "/" + shownLabelPart(bottom);
        } else {
            out += latex[at++];
        }
    }
    for (std::size_t at; (at = out.find("ℒ")) != std::string::npos;) out.replace(at, std::string("ℒ").size(), "L");
    return out;  // with the coordinate's subscript as _1
}

bool isColumn(const DisplayItem& item) { return item.value && !item.value->rows.empty() && item.value->rows[0].size() == 1; }

}  // namespace

std::string itemLatexName(const symbolic::DerivationItem& item, const symbolic::Derivation& d) {
    const std::string i = std::to_string(item.index + 1);
    const auto coordinate = [&] { return latexOfSymbol(d.q.at(item.index).get_name()); };
    const auto velocity = [&] { return latexOfSymbol(d.qd.at(item.index).get_name()); };
    switch (item.quantity) {
        case Quantity::DhTable: return R"(\mathrm{DH})";
        case Quantity::LinkTransform: return "A_{" + i + "}";
        case Quantity::Transform: return "T_{" + i + "}^{0}";
        case Quantity::ComPosition: return "p_{c" + i + "}^{0}";
        case Quantity::AngularJacobian: return R"(J_{\omega,)" + i + "}";
        case Quantity::AngularVelocity: return R"(\omega_{)" + i + "}^{0}";
        case Quantity::ComJacobian: return "J_{v,c" + i + "}";
        case Quantity::ComVelocity: return "v_{c" + i + "}^{0}";
        case Quantity::LinkInertia: return "I_{l" + i + "}^{0}";
        case Quantity::PotentialEnergy: return R"(E_{\mathrm{pot}})";
        case Quantity::MotorInertia: return "B_{m}";
        case Quantity::MassMatrix: return "B(q)";
        case Quantity::KineticEnergy: return R"(E_{\mathrm{kin}})";
        case Quantity::GravityVector: return "g(q)";
        case Quantity::CoriolisMatrix: return R"(C(q,\dot{q}))";
        case Quantity::GeneralizedForces: return "Q";
        case Quantity::EquationOfMotion: return R"(\text{equation } )" + i;
        case Quantity::Coordinates: return "q";
        case Quantity::Velocities: return R"(\dot{q})";
        case Quantity::Lagrangian: return R"(\mathcal{L})";
        case Quantity::MomentumPartial: return R"(\frac{\partial \mathcal{L}}{\partial )" + velocity() + "}";
        case Quantity::MomentumRate: return R"(\frac{d}{dt}\frac{\partial \mathcal{L}}{\partial )" + velocity() + "}";
        case Quantity::CoordinatePartial: return R"(\frac{\partial \mathcal{L}}{\partial )" + coordinate() + "}";
        case Quantity::ProportionalGain: return "K_{p}";
        case Quantity::DerivativeGain: return "K_{d}";
        case Quantity::ControlTorque: return R"(\tau_{)" + i + "}";
        case Quantity::ClosedLoop: return R"(\text{closed loop } )" + i;
        case Quantity::NamedQuantity:
        case Quantity::MassMatrixEntry:
        case Quantity::CoriolisEntry:
        case Quantity::GravityEntry:
        case Quantity::ForceEntry: break;
    }
    return item.name;
}

DisplayPtr displayLabel(const std::string& name, const std::string& latexName) {
    auto n = std::make_shared<DisplayNode>();
    n->kind = DisplayKind::Raw;
    n->text = n->plain = n->name = name;
    n->latex = latexName;
    // What the typesetter draws: HEAD_{SUB}^{SUP} read from the LaTeX name; anything
    // else (\frac …) as the plain name.
    auto shown = std::make_shared<DisplayNode>();
    shown->kind = DisplayKind::Symbol;
    std::size_t at = 0;
    int depth = 0;
    while (at < latexName.size() && !(depth == 0 && (latexName[at] == '_' || latexName[at] == '^'))) {
        depth += latexName[at] == '{' ? 1 : latexName[at] == '}' ? -1 : 0;
        ++at;
    }
    const std::string head = latexName.substr(0, at);
    std::string sub, sup;
    while (at < latexName.size() && (latexName[at] == '_' || latexName[at] == '^')) {
        const char kind = latexName[at++];
        (kind == '_' ? sub : sup) = braced(latexName, at);
    }
    if (head.find("\\frac") != std::string::npos) {  // ∂L/∂θ̇₁ with the coordinate's own symbol, in text ∂L/∂θ̇1
        const std::string line = inlineFractions(latexName);
        const std::size_t sub = line.rfind('_');
        shown->text = line.substr(0, sub);
        if (sub != std::string::npos) shown->subShown = line.substr(sub + 1);
        std::erase(shown->text, '_');
        n->text = line;
        std::erase(n->text, '_');  // θ_1 → θ1, as the expressions write it
    } else if (head.find("\\text") != std::string::npos || at < latexName.size()) {
        shown->text = name;
        shown->upright = true;
    } else {
        shown->text = shownLabelPart(head);
        shown->subShown = shownLabelPart(sub);
        shown->subUpright = sub.find("\\mathrm") != std::string::npos;
        shown->supText = shownLabelPart(sup);
    }
    n->children = {shown};
    return n;
}

std::string entryName(const DisplayItem& item, std::size_t r, std::size_t c) {
    const bool column = isColumn(item);
    if (const std::string letter = entryLetter(item); !letter.empty())
        return letter + std::to_string(r + 1) + (column ? "" : std::to_string(c + 1));
    std::string name = item.name + "[" + std::to_string(r + 1);
    if (!column) name.append(",").append(std::to_string(c + 1));
    return name + "]";
}

DisplayPtr entryLabel(const DisplayItem& item, std::size_t r, std::size_t c) {
    const std::string indices = std::to_string(r + 1) + (isColumn(item) ? "" : std::to_string(c + 1));
    auto label = std::make_shared<DisplayNode>();
    label->kind = DisplayKind::Symbol;
    if (const std::string letter = entryLetter(item); !letter.empty()) {
        label->text = letter;
        label->subShown = indices;
        return label;
    }
    const DisplayNode* lhs = item.equation && item.equation->kind == DisplayKind::Equation ? item.equation->children[0].get() : nullptr;
    if (lhs && lhs->kind == DisplayKind::Raw && !lhs->children.empty() && lhs->children[0]->kind == DisplayKind::Symbol &&
        !lhs->children[0]->upright) {
        *label = *lhs->children[0];
        label->subShown += (label->subShown.empty() ? "" : ",") + indices;
        return label;
    }
    label->text = item.name;
    label->subShown = indices;
    label->upright = true;
    return label;
}

}  // namespace ll::present
