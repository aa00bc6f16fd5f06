#include "core/present/symbol_names.hpp"

#include <algorithm>
#include <cctype>
#include <memory>
#include <string_view>

#include "core/symbolic/trig_names.hpp"

namespace ll::present {
namespace {

bool allDigits(std::string_view s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

struct Greek {
    std::string_view name;
    const char* text;
    const char* latex;
};
constexpr Greek greekLetters[] = {
    {"alpha", "α", "\\alpha"},     {"beta", "β", "\\beta"},
    {"gamma", "γ", "\\gamma"},     {"delta", "δ", "\\delta"},
    {"epsilon", "ε", "\\epsilon"}, {"varepsilon", "ε", "\\varepsilon"},
    {"zeta", "ζ", "\\zeta"},       {"eta", "η", "\\eta"},
    {"theta", "θ", "\\theta"},     {"vartheta", "ϑ", "\\vartheta"},
    {"iota", "ι", "\\iota"},       {"kappa", "κ", "\\kappa"},
    {"lambda", "λ", "\\lambda"},   {"mu", "μ", "\\mu"},
    {"nu", "ν", "\\nu"},           {"xi", "ξ", "\\xi"},
    {"pi", "π", "\\pi"},           {"rho", "ρ", "\\rho"},
    {"sigma", "σ", "\\sigma"},     {"tau", "τ", "\\tau"},
    {"upsilon", "υ", "\\upsilon"}, {"phi", "φ", "\\phi"},
    {"varphi", "φ", "\\varphi"},   {"chi", "χ", "\\chi"},
    {"psi", "ψ", "\\psi"},         {"omega", "ω", "\\omega"},
    {"Gamma", "Γ", "\\Gamma"},     {"Delta", "Δ", "\\Delta"},
    {"Theta", "Θ", "\\Theta"},     {"Lambda", "Λ", "\\Lambda"},
    {"Xi", "Ξ", "\\Xi"},           {"Pi", "Π", "\\Pi"},
    {"Sigma", "Σ", "\\Sigma"},     {"Upsilon", "Υ", "\\Upsilon"},
    {"Phi", "Φ", "\\Phi"},         {"Psi", "Ψ", "\\Psi"},
    {"Omega", "Ω", "\\Omega"},
};

const Greek* greek(std::string_view letters) {
    for (const Greek& g : greekLetters)
        if (letters == g.name) return &g;
    return nullptr;
}

std::string_view letterPrefix(std::string_view name) {
    std::size_t i = 0;
    while (i < name.size() && std::isalpha(static_cast<unsigned char>(name[i]))) ++i;
    return name.substr(0, i);
}

// One piece of a subscript: 1, c, \alpha, \mathrm{cart}.
std::string latexSubscriptPiece(std::string_view piece) {
    if (allDigits(piece) || piece.size() == 1) return latexEscape(std::string(piece));
    // a letter and its index, as in xc1: the reference's q_d1 → q_{d1}
    if (std::islower(static_cast<unsigned char>(piece[0])) && allDigits(piece.substr(1))) return std::string(piece);
    if (const Greek* g = greek(piece)) return g->latex;
    return "\\mathrm{" + latexEscape(std::string(piece)) + "}";
}

struct LatexName {
    std::string head, sub;
    bool word = false;  // a \mathrm{...} head
};

// theta1 → \theta_{1}, lc2 → \ell_{c2}, Ixx1 → I_{xx,1}, xc1 → x_{c1}, m_cart → m_{\mathrm{cart}}.
LatexName latexName(std::string_view name) {
    for (std::string_view p : {"Ixx", "Iyy", "Izz", "Ixy", "Ixz", "Iyz"})
        if (name.starts_with(p) && allDigits(name.substr(3)))
            return {"I", std::string(name.substr(1, 2)) + "," + std::string(name.substr(3))};
    if (name.starts_with("lc") && allDigits(name.substr(2))) return {"\\ell", std::string(name.substr(1))};
    if (const auto underscore = name.find('_'); underscore != std::string_view::npos && underscore > 0) {
        LatexName base = latexName(name.substr(0, underscore));
        const std::string_view rest = name.substr(underscore + 1);
        std::string sub;
        for (std::size_t start = 0; start <= rest.size();) {
            const std::size_t end = std::min(rest.find('_', start), rest.size());
            if (!sub.empty()) sub += ',';
            sub += latexSubscriptPiece(rest.substr(start, end - start));
            start = end + 1;
        }
        if (!base.sub.empty()) base.sub += ',';
        base.sub += sub;
        return base;
    }
    const std::string_view letters = letterPrefix(name), rest = name.substr(letters.size());
    if (letters.empty() || !(rest.empty() || allDigits(rest))) return {"\\mathrm{" + latexEscape(std::string(name)) + "}", "", true};
    if (const Greek* g = greek(letters)) return {g->latex, std::string(rest)};
    if (letters.size() == 1) return {std::string(letters), std::string(rest)};
    if (letters.size() == 2 && std::islower(static_cast<unsigned char>(letters[1])) && !rest.empty())
        return {std::string(letters.substr(0, 1)), std::string(letters.substr(1)) + std::string(rest)};  // xc1, Fc1, vs1
    return {"\\mathrm{" + std::string(letters) + "}", std::string(rest), true};
}

// θ1, ℓc2: the name as text prints it.
std::string textName(const std::string& name) {
    if (name.starts_with("lc") && allDigits(std::string_view(name).substr(2))) return "ℓ" + name.substr(1);
    const std::string_view letters = letterPrefix(name);
    if (const Greek* g = greek(letters)) return g->text + name.substr(letters.size());
    return name;
}

// The symbol node of a name (not a c/s shorthand): base and subscript split the way
// LaTeX splits them, Text printing exactly textName(name).
std::shared_ptr<DisplayNode> namedSymbol(const std::string& name) {
    const std::string textWhole = textName(name);
    auto n = std::make_shared<DisplayNode>();
    n->kind = DisplayKind::Symbol;
    n->name = n->plain = name;
    const LatexName l = latexName(name);
    n->latex = l.head;
    n->subLatex = l.sub;
    n->upright = l.word;
    n->text = shownFromLatex(l.head);
    n->subShown = shownFromLatex(l.sub, &n->subUpright);
    if (l.word || !textWhole.starts_with(n->text)) {
        n->text = textWhole;  // a word, or a head Text spells differently: the whole name, its subscript drawn apart
        return n;
    }
    n->subText = textWhole.substr(n->text.size());
    return n;
}

bool isCoordinate(const std::string& name, const NameRules& rules) {
    if (rules.coordinateNames.empty()) return name.starts_with("q") && allDigits(std::string_view(name).substr(1));
    return std::find(rules.coordinateNames.begin(), rules.coordinateNames.end(), name) != rules.coordinateNames.end();
}

}  // namespace

std::string latexEscape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '^' || c == '~' || c == '\\') continue;
        if (std::string_view("_#%&${}").find(c) != std::string_view::npos) out += '\\';
        out += c;
    }
    return out;
}

std::string shownFromLatex(const std::string& latex, bool* upright) {
    std::string out;
    for (std::size_t i = 0; i < latex.size();) {
        if (latex[i] == '\\') {
            std::size_t j = i + 1;
            while (j < latex.size() && std::isalpha(static_cast<unsigned char>(latex[j]))) ++j;
            const std::string_view command = std::string_view(latex).substr(i + 1, j - i - 1);
            if (command == "mathrm") {
                if (upright) *upright = true;
            } else if (command == "ell") {
                out += "ℓ";
            } else if (const Greek* g = greek(command)) {
                out += g->text;
            }
            i = j;
            continue;
        }
        if (latex[i] != '{' && latex[i] != '}') out += latex[i];
        ++i;
    }
    return out;
}

SymbolMeaning symbolMeaning(const std::string& name, const NameRules& rules) {
    SymbolMeaning m;
    if (rules.trigSymbols)
        if (auto t = symbolic::parseTrigName(name, static_cast<int>(rules.coordinateNames.size()))) {
            m.role = SymbolRole::Trig;
            m.indices = t->indices;
            m.trigKind = t->kind;
            return m;
        }
    std::string stem = name;
    const std::string_view view = name;
    if (view.starts_with("qdd") && allDigits(view.substr(3))) {  // accelerations: q̈1
        m.role = SymbolRole::Velocity;
        m.second = true;
        stem = m.base = std::string("q").append(name, 3);
    } else if (view.starts_with("qd") && allDigits(view.substr(2))) {
        m.role = SymbolRole::Velocity;
        stem = m.base = std::string("q").append(name, 2);
    } else if (view.ends_with("_dot") || view.ends_with("_ddot")) {
        m.role = SymbolRole::Velocity;
        m.second = view.ends_with("_ddot");
        stem = m.base = name.substr(0, name.size() - (m.second ? 5 : 4));
    } else if (isCoordinate(name, rules)) {
        m.role = SymbolRole::Coordinate;
    } else if (name == "m" || (name.starts_with("m") && (allDigits(view.substr(1)) || name[1] == '_'))) {
        m.role = SymbolRole::Mass;
    }
    const auto at = std::find(rules.coordinateNames.begin(), rules.coordinateNames.end(), stem);
    if (at != rules.coordinateNames.end()) {
        m.indices = {static_cast<int>(at - rules.coordinateNames.begin()) + 1};
    } else {
        std::size_t d = stem.size();
        while (d > 0 && std::isdigit(static_cast<unsigned char>(stem[d - 1]))) --d;
        if (d < stem.size() && stem.size() - d < 9) m.indices = {std::stoi(stem.substr(d))};
    }
    return m;
}

DisplayPtr symbolNode(const std::string& name, const SymbolMeaning& meaning, const NameRules& rules) {
    if (name.size() > 4 && name.ends_with("_hat")) {  // an estimate: g1_hat → ĝ_1, b12_hat → b̂_12
        auto n = namedSymbol(name.substr(0, name.size() - 4));
        n->name = n->plain = name;
        n->hat = true;
        return n;
    }
    if (meaning.role == SymbolRole::Trig) {
        auto n = std::make_shared<DisplayNode>();
        n->kind = DisplayKind::Symbol;
        n->name = name;
        const int coordinates = static_cast<int>(rules.coordinateNames.size());
        std::string angle;
        for (int k : meaning.indices) {
            if (!angle.empty()) angle += '+';
            angle += k <= coordinates ? rules.coordinateNames[k - 1] : std::string("q").append(std::to_string(k));
        }
        n->plain = (meaning.trigKind == 'c' ? "cos(" : "sin(") + angle + ")";
        const bool joined = name.find('_') != std::string::npos;  // c9_10 keeps its comma: c_{9,10}
        std::string sub;
        for (int k : meaning.indices) {
            if (!sub.empty() && joined) sub += ',';
            sub += std::to_string(k);
        }
        n->text = n->latex = std::string(1, meaning.trigKind);
        n->subText = n->subLatex = n->subShown = sub;
        return n;
    }
    if (meaning.role == SymbolRole::Velocity) {
        auto n = namedSymbol(meaning.base);
        n->name = n->plain = name;
        n->dots = meaning.second ? 2 : 1;
        return n;
    }
    auto n = namedSymbol(name);
    if (const auto it = rules.links.find(name); it != rules.links.end()) n->link = static_cast<std::int16_t>(it->second);
    return n;
}

DisplayPtr displaySymbolName(const std::string& name, int dots) {
    auto n = namedSymbol(name);
    n->dots = dots;
    return n;
}

}  // namespace ll::present
