#include "core/symbolic/expression_printer.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <climits>
#include <cstdio>
#include <map>
#include <optional>
#include <sstream>
#include <tuple>

#include "core/symbolic/angle_sums.hpp"

namespace ll::symbolic {
namespace {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::is_a;
using GiNaC::numeric;

// ---------------------------------------------------------------- names

bool allDigits(const std::string& s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}
bool startsWith(const std::string& s, const std::string& p) { return s.compare(0, p.size(), p) == 0; }
bool endsWith(const std::string& s, const std::string& p) {
    return s.size() >= p.size() && s.compare(s.size() - p.size(), p.size(), p) == 0;
}

struct Greek {
    const char* name;
    const char* text;
    const char* latex;
};
constexpr Greek greekLetters[] = {
    {"alpha", "α", "\\alpha"},     {"beta", "β", "\\beta"},       {"gamma", "γ", "\\gamma"},
    {"delta", "δ", "\\delta"},     {"epsilon", "ε", "\\epsilon"}, {"varepsilon", "ε", "\\varepsilon"},
    {"zeta", "ζ", "\\zeta"},       {"eta", "η", "\\eta"},         {"theta", "θ", "\\theta"},
    {"vartheta", "ϑ", "\\vartheta"}, {"iota", "ι", "\\iota"},     {"kappa", "κ", "\\kappa"},
    {"lambda", "λ", "\\lambda"},   {"mu", "μ", "\\mu"},           {"nu", "ν", "\\nu"},
    {"xi", "ξ", "\\xi"},           {"pi", "π", "\\pi"},           {"rho", "ρ", "\\rho"},
    {"sigma", "σ", "\\sigma"},     {"tau", "τ", "\\tau"},         {"upsilon", "υ", "\\upsilon"},
    {"phi", "φ", "\\phi"},         {"varphi", "φ", "\\varphi"},   {"chi", "χ", "\\chi"},
    {"psi", "ψ", "\\psi"},         {"omega", "ω", "\\omega"},     {"Gamma", "Γ", "\\Gamma"},
    {"Delta", "Δ", "\\Delta"},     {"Theta", "Θ", "\\Theta"},     {"Lambda", "Λ", "\\Lambda"},
    {"Xi", "Ξ", "\\Xi"},           {"Pi", "Π", "\\Pi"},           {"Sigma", "Σ", "\\Sigma"},
    {"Upsilon", "Υ", "\\Upsilon"}, {"Phi", "Φ", "\\Phi"},         {"Psi", "Ψ", "\\Psi"},
    {"Omega", "Ω", "\\Omega"},
};
const Greek* greek(const std::string& letters) {
    for (const Greek& g : greekLetters)
        if (letters == g.name) return &g;
    return nullptr;
}

// The leading run of letters of a name.
std::string letterPrefix(const std::string& name) {
    std::size_t i = 0;
    while (i < name.size() && std::isalpha(static_cast<unsigned char>(name[i]))) ++i;
    return name.substr(0, i);
}

// For \mathrm{}: escapes what LaTeX would read as markup; ^ ~ \ have no math-mode
// form there and are left out (GiNaC symbol names from scenes are identifiers anyway).
std::string latexEscape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '^' || c == '~' || c == '\\') continue;
        if (std::string("_#%&${}").find(c) != std::string::npos) out += '\\';
        out += c;
    }
    return out;
}

// One piece of a subscript: 1, c, \alpha, \mathrm{cart}.
std::string latexSubscriptPiece(const std::string& piece) {
    if (allDigits(piece) || piece.size() == 1) return latexEscape(piece);
    if (const Greek* g = greek(piece)) return g->latex;
    return "\\mathrm{" + latexEscape(piece) + "}";
}

struct LatexName {
    std::string head, sub;
    bool word = false;  // \mathrm{...} head: wants \, next to other factors
    std::string str() const { return sub.empty() ? head : head + "_{" + sub + "}"; }
};

// theta1 → \theta_{1}, lc2 → \ell_{c2}, Ixx1 → I_{xx,1}, xc1 → x_{c1}, m_cart → m_{\mathrm{cart}}.
LatexName latexName(const std::string& name) {
    static const char* inertia[] = {"Ixx", "Iyy", "Izz", "Ixy", "Ixz", "Iyz"};
    for (const char* p : inertia)
        if (startsWith(name, p) && allDigits(name.substr(3))) return {"I", name.substr(1, 2) + "," + name.substr(3)};
    if (startsWith(name, "lc") && allDigits(name.substr(2))) return {"\\ell", name.substr(1)};
    if (const auto underscore = name.find('_'); underscore != std::string::npos && underscore > 0) {
        LatexName base = latexName(name.substr(0, underscore));
        std::string rest = name.substr(underscore + 1), sub;
        for (std::size_t start = 0; start <= rest.size();) {
            const std::size_t end = std::min(rest.find('_', start), rest.size());
            sub += (sub.empty() ? "" : ",") + latexSubscriptPiece(rest.substr(start, end - start));
            start = end + 1;
        }
        base.sub += (base.sub.empty() ? "" : ",") + sub;
        return base;
    }
    const std::string letters = letterPrefix(name), rest = name.substr(letters.size());
    if (letters.empty() || !(rest.empty() || allDigits(rest))) return {"\\mathrm{" + latexEscape(name) + "}", "", true};
    if (const Greek* g = greek(letters)) return {g->latex, rest};
    if (letters.size() == 1) return {letters, rest};
    if (letters.size() == 2 && std::islower(static_cast<unsigned char>(letters[1])) && !rest.empty())
        return {letters.substr(0, 1), letters.substr(1) + rest};  // xc1, Fc1, vs1
    return {"\\mathrm{" + letters + "}", rest, true};
}

// θ1, ℓc2; a combining mark after the first code point dots it (θ̇1, ẋ).
std::string textName(const std::string& name) {
    if (startsWith(name, "lc") && allDigits(name.substr(2))) return "ℓ" + name.substr(1);
    const std::string letters = letterPrefix(name);
    if (const Greek* g = greek(letters)) return g->text + name.substr(letters.size());
    return name;
}

std::string withMark(const std::string& text, const char* mark) {
    std::size_t first = 1;
    while (first < text.size() && (static_cast<unsigned char>(text[first]) & 0xC0) == 0x80) ++first;
    return text.substr(0, first) + mark + text.substr(first);
}

enum class Kind { Mass, Parameter, Coordinate, Trig, Velocity };

struct SymbolInfo {
    Kind kind = Kind::Parameter;
    std::vector<int> indices;  // the trig index set, or the one index; empty: none
    std::string base;          // a velocity's coordinate name (theta1 for theta1_dot)
    std::optional<TrigName> trig;
    bool second = false;       // _ddot
};

// -------------------------------------------------------------- numbers

std::string str(const numeric& n) {
    std::ostringstream s;
    s << n;
    return s.str();
}

// Shortest decimal that reads back as the same double (for people).
std::string shortest(double v) {
    char buffer[64];
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
    return std::string(buffer, r.ptr);
}

// 17 significant digits, always a float literal for GiNaC's parser (2.0, not 2).
std::string seventeen(double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    std::string s = buffer;
    if (s.find_first_of(".ni") == std::string::npos) {
        const auto e = s.find('e');
        s.insert(e == std::string::npos ? s.size() : e, ".0");
    }
    return s;
}

std::string superscript(const std::string& digits) {
    static const char* sup[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
    std::string out;
    for (char c : digits) out += c == '-' ? "⁻" : (c >= '0' && c <= '9' ? sup[c - '0'] : std::string(1, c));
    return out;
}

// ------------------------------------------------------------- printing

enum Prec { Sum = 0, Product = 1, Power = 2, Atom = 3 };

struct Out {
    std::string s;
    Prec prec = Atom;
    bool word = false;  // a function or \mathrm name (LaTeX puts \, beside it)
};

struct Factor {
    ex base;
    numeric exp;           // numeric; a symbolic power is its own base with exp 1
    bool negated = false;  // a sum shown with its signs flipped (see decompose)
};

// coef · Π num / Π den, the factors in display order.
struct Decomposed {
    numeric coef{1};
    std::vector<Factor> num, den;
};

struct TermKey {
    std::vector<int> velocities;  // indices of the velocity factors, with repetition
    int maxIndex = -1;            // of every other symbol
    bool trig = false;
    numeric degree;
    std::string text;  // Plain, without the coefficient
    double coef = 0;
};

bool operator<(const TermKey& a, const TermKey& b) {
    if (a.velocities != b.velocities) return a.velocities < b.velocities;
    if (a.maxIndex != b.maxIndex) return a.maxIndex < b.maxIndex;
    if (a.trig != b.trig) return !a.trig;
    if (a.degree != b.degree) return a.degree < b.degree;
    if (a.text != b.text) return a.text < b.text;
    return a.coef < b.coef;
}

struct Term {
    ex e;
    std::optional<Decomposed> d;  // none for a number
    TermKey key;
    bool negative() const {
        const numeric& c = d ? d->coef : ex_to<numeric>(e);
        return c.is_real() && c.is_negative();
    }
};

class Printer {
public:
    Printer(const PrintOptions& o, bool key) : o_(o), style_(key ? Style::Plain : o.style), key_(key) {
        n_ = static_cast<int>(o.coordinateNames.size());
    }

    Out render(const ex& e) const {
        if (is_a<GiNaC::add>(e)) return renderSum(e, false);
        if (is_a<numeric>(e)) return renderNumber(ex_to<numeric>(e));
        if (is_a<GiNaC::relational>(e) || is_a<GiNaC::lst>(e)) return renderAtom(e);
        Decomposed d = decompose(e);
        if (!d.coef.is_real() || !d.coef.is_negative()) return renderProduct(d);
        d.coef = -d.coef;
        return {minus() + renderProduct(d).s, Sum};
    }

private:
    const PrintOptions& o_;
    Style style_;
    bool key_;
    int n_ = 0;

    // ---- symbols

    SymbolInfo info(const GiNaC::symbol& s) const {
        const std::string& name = s.get_name();
        SymbolInfo i;
        if (o_.trigSymbols) {
            if (auto t = parseTrigName(name, n_)) {
                i.kind = Kind::Trig;
                i.indices = t->indices;
                i.trig = t;
                return i;
            }
        }
        std::string stem = name;
        if (startsWith(name, "qdd") && allDigits(name.substr(3))) {  // accelerations: q̈1
            i.kind = Kind::Velocity;
            i.second = true;
            stem = i.base = "q" + name.substr(3);
        } else if (startsWith(name, "qd") && allDigits(name.substr(2))) {
            i.kind = Kind::Velocity;
            stem = i.base = "q" + name.substr(2);
        } else if (endsWith(name, "_dot") || endsWith(name, "_ddot")) {
            i.kind = Kind::Velocity;
            i.second = endsWith(name, "_ddot");
            stem = i.base = name.substr(0, name.size() - (i.second ? 5 : 4));
        } else if (isCoordinate(name)) {
            i.kind = Kind::Coordinate;
        } else if (name == "m" || (startsWith(name, "m") && (allDigits(name.substr(1)) || name[1] == '_'))) {
            i.kind = Kind::Mass;
        }
        // The index: a coordinate's position, else the trailing number.
        const auto at = std::find(o_.coordinateNames.begin(), o_.coordinateNames.end(), stem);
        if (at != o_.coordinateNames.end()) {
            i.indices = {static_cast<int>(at - o_.coordinateNames.begin()) + 1};
        } else {
            std::size_t d = stem.size();
            while (d > 0 && std::isdigit(static_cast<unsigned char>(stem[d - 1]))) --d;
            if (d < stem.size() && stem.size() - d < 9) i.indices = {std::stoi(stem.substr(d))};
        }
        return i;
    }

    bool isCoordinate(const std::string& name) const {
        if (o_.coordinateNames.empty()) return startsWith(name, "q") && allDigits(name.substr(1));
        return std::find(o_.coordinateNames.begin(), o_.coordinateNames.end(), name) != o_.coordinateNames.end();
    }

    std::string minus() const { return style_ == Style::Text ? "−" : "-"; }

    // ---- order

    // The terms of a sum in display order.
    std::vector<Term> terms(const ex& sum) const {
        std::vector<Term> out;
        for (const ex& t : sum) {
            Term term{t, std::nullopt, {}};
            if (!is_a<numeric>(t)) term.d = decompose(t);
            term.key = termKey(term);
            out.push_back(std::move(term));
        }
        std::stable_sort(out.begin(), out.end(), [](const Term& a, const Term& b) { return a.key < b.key; });
        return out;
    }

    TermKey termKey(const Term& t) const {
        TermKey k;
        if (!t.d) {
            k.coef = ex_to<numeric>(t.e).is_real() ? ex_to<numeric>(t.e).to_double() : 0.0;
            k.text = "1";
            return k;
        }
        k.coef = t.d->coef.is_real() ? t.d->coef.to_double() : 0.0;
        for (const Factor& f : t.d->num)
            if (is_a<GiNaC::symbol>(f.base) && f.exp.is_pos_integer()) {
                const SymbolInfo i = info(ex_to<GiNaC::symbol>(f.base));
                if (i.kind == Kind::Velocity)
                    k.velocities.insert(k.velocities.end(), f.exp.to_int(), i.indices.empty() ? 0 : i.indices.back());
            }
        std::sort(k.velocities.begin(), k.velocities.end());
        scan(t.e, k);
        k.degree = degree(t.e);
        k.text = key_ ? renderProduct(*t.d, false).s : Printer(o_, true).renderProduct(*t.d, false).s;
        return k;
    }

    void scan(const ex& e, TermKey& k) const {
        for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
            if (is_a<GiNaC::symbol>(*it)) {
                const SymbolInfo i = info(ex_to<GiNaC::symbol>(*it));
                if (i.kind == Kind::Trig) k.trig = true;
                if (i.kind != Kind::Velocity && !i.indices.empty())
                    k.maxIndex = std::max(k.maxIndex, *std::max_element(i.indices.begin(), i.indices.end()));
            } else if (is_a<GiNaC::function>(*it)) {
                const std::string name = ex_to<GiNaC::function>(*it).get_name();
                if (name == "sin" || name == "cos" || name == "tan") k.trig = true;
            }
        }
    }

    static numeric degree(const ex& e) {
        if (is_a<numeric>(e) || is_a<GiNaC::constant>(e)) return 0;
        if (is_a<GiNaC::add>(e)) {
            numeric d = 0;
            for (const ex& t : e)
                if (const numeric dt = degree(t); d < dt) d = dt;
            return d;
        }
        if (is_a<GiNaC::mul>(e)) {
            numeric d = 0;
            for (const ex& f : e) d += degree(f);
            return d;
        }
        if (is_a<GiNaC::power>(e) && is_a<numeric>(e.op(1)) && ex_to<numeric>(e.op(1)).is_real())
            return degree(e.op(0)) * ex_to<numeric>(e.op(1));
        return 1;
    }

    // GiNaC gives a sum factor with an integer power the sign that makes its leading
    // term positive in GiNaC's hash order, which varies: (b−a)² or (a−b)². Shown here
    // with the leading term in *our* order positive, an odd power's sign moved to coef.
    Decomposed decompose(const ex& e) const {
        Decomposed d;
        auto one = [&](const ex& x) {
            if (is_a<numeric>(x)) {
                d.coef *= ex_to<numeric>(x);
                return;
            }
            Factor f{x, 1};
            if (is_a<GiNaC::power>(x) && is_a<numeric>(x.op(1)) && ex_to<numeric>(x.op(1)).is_real())
                f = {x.op(0), ex_to<numeric>(x.op(1))};
            if (is_a<GiNaC::add>(f.base) && f.exp.is_integer() && terms(f.base).front().negative()) {
                f.negated = true;
                if (f.exp.is_odd()) d.coef = -d.coef;
            }
            if (f.exp.is_negative()) {
                f.exp = -f.exp;
                d.den.push_back(f);
            } else {
                d.num.push_back(f);
            }
        };
        if (is_a<GiNaC::mul>(e))
            for (const ex& x : e) one(x);
        else
            one(e);
        auto order = [this](const Factor& a, const Factor& b) { return factorKey(a) < factorKey(b); };
        std::stable_sort(d.num.begin(), d.num.end(), order);
        std::stable_sort(d.den.begin(), d.den.end(), order);
        return d;
    }

    // Number, constants, masses, parameters, coordinates, c/s, functions, sums, velocities.
    std::tuple<int, std::vector<int>, std::string> factorKey(const Factor& f) const {
        const ex& b = f.base;
        const Printer key(o_, true);
        if (is_a<numeric>(b) || is_a<GiNaC::constant>(b)) return {0, {}, key.render(b).s};
        if (is_a<GiNaC::symbol>(b)) {
            const SymbolInfo i = info(ex_to<GiNaC::symbol>(b));
            static const int rank[] = {1, 2, 3, 4, 7};  // by Kind; functions 5, sums 6
            std::vector<int> sub = i.indices.empty() ? std::vector<int>{INT_MAX} : i.indices;
            if (i.trig) sub.push_back(i.trig->kind == 'c' ? 0 : 1);  // c1 before s1
            return {rank[static_cast<int>(i.kind)], sub, ex_to<GiNaC::symbol>(b).get_name()};
        }
        if (is_a<GiNaC::add>(b)) return {6, {}, key.renderSum(b, f.negated).s};
        return {is_a<GiNaC::function>(b) ? 5 : 6, {}, key.render(b).s};
    }

    // ---- sums

    Out renderSum(const ex& e, bool negated) const {
        std::string s;
        const bool plain = style_ == Style::Plain;
        bool first = true;
        for (const Term& t : terms(e)) {
            const bool neg = t.negative() != negated;
            std::string magnitude;
            if (!t.d) {
                magnitude = renderNumber(abs(ex_to<numeric>(t.e))).s;
            } else {
                Decomposed d = *t.d;
                if (d.coef.is_real()) d.coef = abs(d.coef);
                magnitude = renderProduct(d).s;
            }
            if (first)
                s += neg ? minus() : "";
            else
                s += plain ? (neg ? "-" : "+") : (neg ? " " + minus() + " " : " + ");
            s += magnitude;
            first = false;
        }
        return {s, Sum};
    }

    // ---- numbers

    Out renderNumber(const numeric& n) const {
        if (!n.is_real()) {  // not expected in mechanics; GiNaC's form, parenthesised
            std::ostringstream s;
            if (style_ == Style::Latex) s << GiNaC::latex;
            s << n;
            return {"(" + s.str() + ")", Atom};
        }
        if (n.is_negative()) return {minus() + renderNumber(-n).s, Sum};
        if (n.is_integer()) return {str(n), Atom};
        if (n.is_rational()) {
            if (style_ == Style::Latex) return {"\\frac{" + str(n.numer()) + "}{" + str(n.denom()) + "}", Atom};
            return {str(n.numer()) + "/" + str(n.denom()), Product};
        }
        return {style_ == Style::Plain ? seventeen(n.to_double()) : readableFloat(n.to_double()), Atom};
    }

    std::string readableFloat(double v) const {
        const std::string s = shortest(v);
        const auto e = s.find('e');
        if (e == std::string::npos) return s;
        const std::string mantissa = s.substr(0, e), exponent = std::to_string(std::stoi(s.substr(e + 1)));
        if (style_ == Style::Latex) return mantissa + " \\cdot 10^{" + exponent + "}";
        return mantissa + "·10" + superscript(exponent);
    }

    // ---- atoms

    Out renderSymbol(const GiNaC::symbol& sym) const {
        const std::string& name = sym.get_name();
        const SymbolInfo i = info(sym);
        if (i.kind == Kind::Trig) {
            const auto& idx = i.indices;
            if (style_ == Style::Plain && !key_) {
                std::string arg;
                for (int k : idx)
                    arg += (arg.empty() ? "" : "+") +
                           (k <= n_ ? o_.coordinateNames[k - 1] : "q" + std::to_string(k));
                return {(i.trig->kind == 'c' ? "cos(" : "sin(") + arg + ")", Atom};
            }
            if (style_ == Style::Plain) return {name, Atom};
            const bool joined = name.find('_') != std::string::npos;
            std::string sub;
            for (int k : idx) sub += (sub.empty() || !joined ? "" : ",") + std::to_string(k);
            if (style_ == Style::Text) return {std::string(1, i.trig->kind) + sub, Atom};
            return {std::string(1, i.trig->kind) + "_{" + sub + "}", Atom};
        }
        if (style_ == Style::Plain) return {name, Atom};
        if (i.kind == Kind::Velocity) {
            if (style_ == Style::Text) return {withMark(textName(i.base), i.second ? "\u0308" : "\u0307"), Atom};
            LatexName l = latexName(i.base);
            l.head = (i.second ? "\\ddot{" : "\\dot{") + l.head + "}";
            return {l.str(), Atom, l.word};
        }
        if (style_ == Style::Text) return {textName(name), Atom};
        const LatexName l = latexName(name);
        return {l.str(), Atom, l.word};
    }

    Out renderConstant(const ex& c) const {
        std::ostringstream plain;
        plain << c;
        const std::string name = plain.str();
        if (style_ == Style::Plain) return {name, Atom};
        if (name == "Pi") return {style_ == Style::Text ? "π" : "\\pi", Atom};
        if (name == "Euler") return {style_ == Style::Text ? "γ" : "\\gamma", Atom};
        return {style_ == Style::Text ? name : "\\mathrm{" + name + "}", Atom, true};
    }

    std::string functionName(const std::string& name) const {
        if (style_ != Style::Latex) return name;
        static const std::map<std::string, std::string> known = {
            {"sin", "\\sin"},       {"cos", "\\cos"},       {"tan", "\\tan"},   {"exp", "\\exp"},
            {"log", "\\ln"},        {"sinh", "\\sinh"},     {"cosh", "\\cosh"}, {"tanh", "\\tanh"},
            {"asin", "\\arcsin"},   {"acos", "\\arccos"},   {"atan", "\\arctan"}};
        const auto it = known.find(name);
        return it != known.end() ? it->second : "\\operatorname{" + latexEscape(name) + "}";
    }

    // name, the power written on it in Text/LaTeX (sin²(x)), and the arguments.
    Out renderFunction(const ex& f, const std::string& power = "") const {
        const std::string name = ex_to<GiNaC::function>(f).get_name();
        std::string args;
        for (const ex& a : f) args += (args.empty() ? "" : (style_ == Style::Plain ? "," : ", ")) + render(a).s;
        if (name == "abs" && style_ != Style::Plain) {
            const std::string bars = style_ == Style::Latex ? "\\left|" + args + "\\right|" : "|" + args + "|";
            return {bars + power, power.empty() ? Atom : Power};
        }
        return {functionName(name) + power + "(" + args + ")", Atom, style_ == Style::Latex};
    }

    // c12 == cos(q1+q2) in Plain (GiNaC's spelling), c12 = cos(q1 + q2) otherwise.
    Out renderRelational(const GiNaC::relational& r) const {
        using GiNaC::info_flags;
        struct Op {
            unsigned flag;
            const char *plain, *text, *latex;
        };
        static const Op ops[] = {{info_flags::relation_equal, "==", "=", "="},
                                 {info_flags::relation_not_equal, "!=", "≠", "\\neq"},
                                 {info_flags::relation_less, "<", "<", "<"},
                                 {info_flags::relation_less_or_equal, "<=", "≤", "\\leq"},
                                 {info_flags::relation_greater, ">", ">", ">"},
                                 {info_flags::relation_greater_or_equal, ">=", "≥", "\\geq"}};
        const Op* op = &ops[0];
        for (const Op& o : ops)
            if (r.info(o.flag)) op = &o;
        const std::string lhs = render(r.lhs()).s, rhs = render(r.rhs()).s;
        if (style_ == Style::Plain) return {lhs + op->plain + rhs, Sum};
        return {lhs + " " + (style_ == Style::Latex ? op->latex : op->text) + " " + rhs, Sum};
    }

    Out renderAtom(const ex& e) const {
        if (is_a<GiNaC::symbol>(e)) return renderSymbol(ex_to<GiNaC::symbol>(e));
        if (is_a<GiNaC::constant>(e)) return renderConstant(e);
        if (is_a<GiNaC::function>(e)) return renderFunction(e);
        if (is_a<numeric>(e)) return renderNumber(ex_to<numeric>(e));
        if (is_a<GiNaC::add>(e)) return renderSum(e, false);
        if (is_a<GiNaC::power>(e)) {  // symbolic exponent
            const Out b = render(e.op(0)), x = render(e.op(1));
            const std::string base = b.prec < Atom ? paren(b.s) : b.s;
            if (style_ == Style::Latex) return {base + "^{" + x.s + "}", Power};
            return {base + "^" + (x.prec < Atom ? "(" + x.s + ")" : x.s), Power};
        }
        if (is_a<GiNaC::mul>(e)) return render(e);
        if (is_a<GiNaC::relational>(e)) return renderRelational(ex_to<GiNaC::relational>(e));
        if (is_a<GiNaC::lst>(e)) {
            std::string items;
            for (const ex& item : e) items += (items.empty() ? "" : (style_ == Style::Plain ? "," : ", ")) + render(item).s;
            return {style_ == Style::Latex ? "\\left\\{" + items + "\\right\\}" : "{" + items + "}", Atom};
        }
        std::ostringstream s;  // other GiNaC classes: its own printer
        if (style_ == Style::Latex) s << GiNaC::latex;
        s << e;
        return {"(" + s.str() + ")", Atom};
    }

    std::string paren(const std::string& s) const {
        return style_ == Style::Latex ? "\\left(" + s + "\\right)" : "(" + s + ")";
    }

    // ---- products

    Out renderFactor(const Factor& f) const {
        const numeric& k = f.exp;
        const Out b = f.negated ? renderSum(f.base, true) : renderAtom(f.base);
        if (k == 1) return b.prec <= Product ? Out{paren(b.s), Atom} : b;
        if (k == numeric(1, 2)) {
            if (style_ == Style::Latex) return {"\\sqrt{" + b.s + "}", Atom};
            if (style_ == Style::Plain) return {"sqrt(" + b.s + ")", Atom};
            return {"√" + (b.prec < Atom ? paren(b.s) : b.s), Atom};
        }
        const std::string power = str(k);
        if (is_a<GiNaC::function>(f.base) && style_ != Style::Plain && k.is_pos_integer())
            return renderFunction(f.base, style_ == Style::Text ? superscript(power) : "^{" + power + "}");
        const std::string base = b.prec < Atom ? paren(b.s) : b.s;
        if (style_ == Style::Latex) return {(b.prec < Atom ? "{" + base + "}" : base) + "^{" + power + "}", Power};
        if (style_ == Style::Text && k.is_integer()) return {base + superscript(power), Power};
        const std::string exponent = k.is_integer() ? power : "(" + (k.is_rational() ? power : seventeen(k.to_double())) + ")";
        return {base + "^" + exponent, Power};
    }

    // Factors side by side: * in Plain; a space (· before a digit) in Text; in LaTeX a
    // space, \, beside functions and words, \cdot before a digit.
    std::string join(const std::vector<Out>& pieces) const {
        std::string s;
        for (std::size_t i = 0; i < pieces.size(); ++i) {
            if (i > 0) {
                const bool digit = std::isdigit(static_cast<unsigned char>(pieces[i].s[0]));
                if (style_ == Style::Plain)
                    s += "*";
                else if (style_ == Style::Text)
                    s += digit ? "·" : " ";
                else
                    s += digit ? " \\cdot " : (pieces[i].word || pieces[i - 1].word ? "\\, " : " ");
            }
            s += pieces[i].s;
        }
        return s;
    }

    // The product as decomposed (its sign is the caller's: coef ≥ 0 here).
    Out renderProduct(const Decomposed& d, bool withCoefficient = true) const {
        const numeric c = withCoefficient ? d.coef : numeric(1);
        std::vector<Out> num, den;
        if (d.den.empty() || !c.is_rational()) {
            if (c != 1) num.push_back(renderNumber(c));  // 2, 1/2, \frac{1}{2}, 0.5 in front
        } else {
            if (c.numer() != 1) num.push_back(renderNumber(c.numer()));
            if (c.denom() != 1) den.push_back(renderNumber(c.denom()));
        }
        const bool numCoef = !num.empty(), denCoef = !den.empty();
        for (const Factor& f : d.num) num.push_back(renderFactor(f));
        for (const Factor& f : d.den) den.push_back(renderFactor(f));
        if (den.empty()) {
            if (num.empty()) return {"1", Atom};
            return num.size() == 1 ? num[0] : Out{join(num), Product};
        }
        if (style_ == Style::Latex) {
            // A lone sum needs no parentheses inside \frac.
            auto side = [&](const std::vector<Out>& pieces, const std::vector<Factor>& fs, bool coef) {
                if (pieces.empty()) return std::string("1");
                if (!coef && fs.size() == 1 && fs[0].exp == 1 && is_a<GiNaC::add>(fs[0].base))
                    return renderSum(fs[0].base, fs[0].negated).s;
                return join(pieces);
            };
            return {"\\frac{" + side(num, d.num, numCoef) + "}{" + side(den, d.den, denCoef) + "}", Atom};
        }
        const std::string top = num.empty() ? "1" : join(num);
        const bool bare = den.size() == 1 && den[0].prec >= Power;  // a/b, a/b^2
        return {top + "/" + (bare ? den[0].s : "(" + join(den) + ")"), Product};
    }
};

// ------------------------------------------------------------ layout

// Code points on screen: combining marks (U+0300–U+036F) take no column.
std::size_t columns(const std::string& s) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < s.size();) {
        const unsigned char b = static_cast<unsigned char>(s[i]);
        const std::size_t len = b < 0x80 ? 1 : b < 0xE0 ? 2 : b < 0xF0 ? 3 : 4;
        if (!(len == 2 && (b == 0xCC || (b == 0xCD && static_cast<unsigned char>(s[i + 1]) < 0xB0)))) ++n;
        i += len;
    }
    return n;
}

std::vector<std::string> lines(const std::string& s) {
    std::vector<std::string> out;
    std::istringstream in(s);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    if (out.empty()) out.emplace_back();
    return out;
}

std::string rtrim(std::string s) {
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
}

}  // namespace

std::string textCoordinateName(const std::string& name, int dots) {
    const std::string text = textName(name);
    return dots == 0 ? text : withMark(text, dots == 1 ? "\u0307" : "\u0308");
}

PrintOptions printOptionsFor(const Derivation& derivation, Style style) {
    PrintOptions o;
    o.style = style;
    o.coordinateNames = derivation.coordinateNames;
    if (o.coordinateNames.empty())
        for (const GiNaC::symbol& q : derivation.q) o.coordinateNames.push_back(q.get_name());
    o.trigSymbols = derivation.trigToFunctions.nops() > 0;
    return o;
}

std::string print(const ex& e, const PrintOptions& options) {
    if (is_a<GiNaC::matrix>(e)) return printMatrix(ex_to<GiNaC::matrix>(e), options);
    return Printer(options, false).render(e).s;
}

std::string printMatrix(const GiNaC::matrix& m, const PrintOptions& options) {
    const unsigned rows = m.rows(), cols = m.cols();
    std::vector<std::vector<std::string>> cell(rows, std::vector<std::string>(cols));
    for (unsigned i = 0; i < rows; ++i)
        for (unsigned j = 0; j < cols; ++j) cell[i][j] = print(m(i, j), options);
    std::string s;
    switch (options.style) {
    case Style::Plain:
        s = "[";
        for (unsigned i = 0; i < rows; ++i) {
            s += i ? ",[" : "[";
            for (unsigned j = 0; j < cols; ++j) s += (j ? "," : "") + cell[i][j];
            s += "]";
        }
        return s + "]";
    case Style::Latex:
        s = "\\begin{bmatrix} ";
        for (unsigned i = 0; i < rows; ++i) {
            if (i) s += " \\\\ ";
            for (unsigned j = 0; j < cols; ++j) s += (j ? " & " : "") + cell[i][j];
        }
        return s + " \\end{bmatrix}";
    case Style::Text:
        break;
    }
    std::vector<std::size_t> width(cols, 0);
    for (unsigned i = 0; i < rows; ++i)
        for (unsigned j = 0; j < cols; ++j) width[j] = std::max(width[j], columns(cell[i][j]));
    for (unsigned i = 0; i < rows; ++i) {
        const bool top = i == 0, bottom = i + 1 == rows;
        s += rows == 1 ? "[ " : top ? "⎡ " : bottom ? "⎣ " : "⎢ ";
        for (unsigned j = 0; j < cols; ++j)
            s += (j ? "  " : "") + cell[i][j] + std::string(width[j] - columns(cell[i][j]), ' ');
        s += rows == 1 ? " ]" : top ? " ⎤" : bottom ? " ⎦" : " ⎥";
        if (!bottom) s += "\n";
    }
    return rows == 0 ? "[ ]" : s;
}

std::string printEquation(const std::string& lhs, const ex& rhs, const PrintOptions& options) {
    const std::string right = print(rhs, options);
    if (options.style != Style::Text) return lhs + " = " + right;
    // Blocks side by side, each centred on the middle line.
    const std::vector<std::string> a = lines(lhs), b = lines(right);
    const std::size_t h = std::max(a.size(), b.size()), mid = (h - 1) / 2;
    std::size_t wa = 0;
    for (const auto& l : a) wa = std::max(wa, columns(l));
    auto at = [h](const std::vector<std::string>& block, std::size_t i) -> std::string {
        const std::size_t top = (h - block.size()) / 2;
        return i >= top && i - top < block.size() ? block[i - top] : std::string();
    };
    std::string s;
    for (std::size_t i = 0; i < h; ++i) {
        const std::string left = at(a, i);
        s += rtrim(left + std::string(wa - columns(left), ' ') + (i == mid ? " = " : "   ") + at(b, i));
        if (i + 1 < h) s += "\n";
    }
    return s;
}

std::string printEquation(const ex& lhs, const ex& rhs, const PrintOptions& options) {
    return printEquation(print(lhs, options), rhs, options);
}

GiNaC::ex collectForDisplay(const ex& e, const std::vector<GiNaC::symbol>& groupBy) {
    if (is_a<GiNaC::matrix>(e)) {
        GiNaC::matrix m = ex_to<GiNaC::matrix>(e);
        for (unsigned i = 0; i < m.rows(); ++i)
            for (unsigned j = 0; j < m.cols(); ++j) m(i, j) = collectForDisplay(m(i, j), groupBy);
        return m;
    }
    const ex x = e.expand();
    if (groupBy.empty()) return x;
    // Exponents of the groupBy symbols → cofactors. A std::map of exponent vectors
    // makes the grouping independent of GiNaC's term order.
    std::map<std::vector<int>, std::vector<ex>> groups;
    ex single = 0;
    auto addTerm = [&](const ex& term) {
        std::vector<int> key(groupBy.size(), 0);
        ex cofactor = term;
        for (std::size_t g = 0; g < groupBy.size(); ++g) {
            const ex& s = groupBy[g];
            for (const ex& f : is_a<GiNaC::mul>(term) ? term : GiNaC::lst{term}) {
                if (f.is_equal(s)) key[g] = 1;
                else if (is_a<GiNaC::power>(f) && f.op(0).is_equal(s) && f.op(1).info(GiNaC::info_flags::posint))
                    key[g] = ex_to<numeric>(f.op(1)).to_int();
            }
            if (key[g]) cofactor = cofactor * GiNaC::pow(s, -key[g]);
        }
        if (std::all_of(key.begin(), key.end(), [](int k) { return k == 0; }))
            single += term;
        else
            groups[key].push_back(cofactor);
    };
    if (is_a<GiNaC::add>(x))
        for (const ex& t : x) addTerm(t);
    else
        addTerm(x);
    ex result = single;
    for (const auto& [key, cofactors] : groups) {
        ex monomial = 1;
        for (std::size_t g = 0; g < groupBy.size(); ++g) monomial *= GiNaC::pow(groupBy[g], key[g]);
        if (cofactors.size() == 1) {
            result += monomial * cofactors[0];
            continue;
        }
        // The common rational factor of the cofactors goes in front: 1/2*m1*(…).
        numeric gcdNum = 0, lcmDen = 1;
        bool rational = true, allNegative = true;
        for (const ex& c : cofactors) {
            numeric k = 1;
            if (is_a<numeric>(c)) k = ex_to<numeric>(c);
            else if (is_a<GiNaC::mul>(c) && is_a<numeric>(c.op(c.nops() - 1))) k = ex_to<numeric>(c.op(c.nops() - 1));
            if (!k.is_rational()) rational = false;
            if (!rational) break;
            gcdNum = GiNaC::gcd(gcdNum, k.numer());
            lcmDen = GiNaC::lcm(lcmDen, k.denom());
            allNegative = allNegative && k.is_negative();
        }
        numeric content = rational ? gcdNum / lcmDen : numeric(1);
        if (allNegative && rational) content = -content;
        ex sum = 0;
        for (const ex& c : cofactors) sum += c / content;
        result += content * monomial * sum;
    }
    return result;
}

std::vector<GiNaC::symbol> massSymbols(const ex& e) {
    std::map<std::pair<long, std::string>, GiNaC::symbol> found;
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
        if (!is_a<GiNaC::symbol>(*it)) continue;
        const std::string& name = ex_to<GiNaC::symbol>(*it).get_name();
        const std::string digits = name.substr(1);
        if (name == "m" || (startsWith(name, "m") && (name[1] == '_' || (allDigits(digits) && digits.size() < 9))))
            found.emplace(std::pair{allDigits(digits) ? std::stol(digits) : -1L, name}, ex_to<GiNaC::symbol>(*it));
    }
    std::vector<GiNaC::symbol> out;
    for (auto& [key, s] : found) out.push_back(s);
    return out;
}

}  // namespace ll::symbolic
