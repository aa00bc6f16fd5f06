#include "core/symbolic/display_builder.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <climits>
#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string_view>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "core/symbolic/angle_sums.hpp"
#include "core/symbolic/ginac_kind.hpp"
#include "core/symbolic/ginac_pairs.hpp"
#include "core/symbolic/readable_numbers.hpp"

namespace ll::symbolic {
namespace {

using GiNaC::ex, GiNaC::ex_to, GiNaC::is_a, GiNaC::numeric;

// ---------------------------------------------------------------- names

// (Views: these run on every symbol name a document shows, and made strings of their
// literals and substrings.)
bool allDigits(std::string_view s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}
bool startsWith(std::string_view s, std::string_view p) { return s.starts_with(p); }
bool endsWith(std::string_view s, std::string_view p) { return s.ends_with(p); }

struct Greek {
    std::string_view name;  // a view: compared by length first (most names are not Greek)
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
const Greek* greek(std::string_view letters) {
    if (letters.size() < 2 || letters.size() > 10) return nullptr;  // mu .. varepsilon
    for (const Greek& g : greekLetters)
        if (letters == g.name) return &g;
    return nullptr;
}

std::string_view letterPrefix(std::string_view name) {
    std::size_t i = 0;
    while (i < name.size() && std::isalpha(static_cast<unsigned char>(name[i]))) ++i;
    return name.substr(0, i);
}

// For \mathrm{}: escapes what LaTeX would read as markup; ^ ~ \ have no math-mode
// form there and are left out (GiNaC symbol names from scenes are identifiers anyway).
std::string latexEscape(std::string_view s) {
    std::string out;
    for (char c : s) {
        if (c == '^' || c == '~' || c == '\\') continue;
        if (std::string_view("_#%&${}").find(c) != std::string_view::npos) out += '\\';
        out += c;
    }
    return out;
}

// One piece of a subscript: 1, c, \alpha, \mathrm{cart}.
std::string latexSubscriptPiece(std::string_view piece) {
    if (allDigits(piece) || piece.size() == 1) return latexEscape(piece);
    if (const Greek* g = greek(piece)) return g->latex;
    return "\\mathrm{" + latexEscape(piece) + "}";
}

struct LatexName {
    std::string head, sub;
    bool word = false;  // \mathrm{...} head
};

// theta1 → \theta_{1}, lc2 → \ell_{c2}, Ixx1 → I_{xx,1}, xc1 → x_{c1}, m_cart → m_{\mathrm{cart}}.
LatexName latexName(std::string_view name) {
    static constexpr std::string_view inertia[] = {"Ixx", "Iyy", "Izz", "Ixy", "Ixz", "Iyz"};
    for (std::string_view p : inertia)
        if (startsWith(name, p) && allDigits(name.substr(3))) {
            std::string sub(name.substr(1, 2));
            sub += ',';
            sub += name.substr(3);
            return {"I", std::move(sub)};
        }
    if (startsWith(name, "lc") && allDigits(name.substr(2))) return {"\\ell", std::string(name.substr(1))};
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
    if (letters.empty() || !(rest.empty() || allDigits(rest))) return {"\\mathrm{" + latexEscape(name) + "}", "", true};
    if (const Greek* g = greek(letters)) return {g->latex, std::string(rest)};
    if (letters.size() == 1) return {std::string(letters), std::string(rest)};
    if (letters.size() == 2 && std::islower(static_cast<unsigned char>(letters[1])) && !rest.empty())
        return {std::string(letters.substr(0, 1)), std::string(letters.substr(1)) + std::string(rest)};  // xc1, Fc1, vs1
    return {"\\mathrm{" + std::string(letters) + "}", std::string(rest), true};
}

// θ1, ℓc2.
std::string textName(const std::string& name) {
    if (startsWith(name, "lc") && allDigits(std::string_view(name).substr(2))) return "ℓ" + name.substr(1);
    const std::string_view letters = letterPrefix(name);
    if (const Greek* g = greek(letters)) return g->text + name.substr(letters.size());
    return name;
}

// A LaTeX head or subscript as the typesetter draws it: \theta → θ, \mathrm{cart} → cart.
std::string shownFromLatex(const std::string& latex, bool* upright = nullptr) {
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

// The symbol node for a name (not a c/s shorthand): base and subscript split the way
// LaTeX splits them, Text printing exactly textName(name).
std::shared_ptr<DisplayNode> namedSymbol(const std::string& name, const std::string& textWhole) {
    auto n = std::make_shared<DisplayNode>();
    n->kind = DisplayKind::Symbol;
    n->name = n->plain = name;
    const LatexName l = latexName(name);
    n->latex = l.head;
    n->subLatex = l.sub;
    n->upright = l.word;
    bool word = false;
    n->text = shownFromLatex(l.head, &word);
    if (l.word || !startsWith(textWhole, n->text)) {
        n->text = textWhole;
        n->subShown = shownFromLatex(l.sub, &n->subUpright);
        if (l.word) return n;
        n->subText.clear();
        return n;
    }
    n->subText = textWhole.substr(n->text.size());
    n->subShown = shownFromLatex(l.sub, &n->subUpright);
    return n;
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

std::string str(const numeric& n) { return (std::ostringstream() << n).str(); }

// Shortest decimal that reads back as the same double (for people).
std::string shortest(double v) {
    char buffer[64];
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
    return std::string(buffer, r.ptr);
}

// A decimal as people read it: the shortest form when it has at most shownDigits
// significant digits (a scene's 0.15005), else rounded to shownDigits (the Panda's
// products of identified inertials, 0.00796990221726315 → 0.0079699). Plain keeps
// every digit (seventeen), so what is re-parsed is exact.
constexpr int shownDigits = 6;
std::string readable(double v) {
    const std::string s = shortest(v);
    int digits = 0;
    bool leading = true;
    for (char c : s) {
        if (c == 'e' || c == 'E') break;
        if (c < '0' || c > '9') continue;
        if (leading && c == '0') continue;
        leading = false;
        ++digits;
    }
    if (digits <= shownDigits) return s;
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*g", shownDigits, v);
    std::string r = buffer;
    // %g writes 1e-05; the caller splits at 'e' and wants the exponent without padding.
    return r;
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

// ------------------------------------------------------------- building

using Prec = int;  // displayPrecedence
constexpr Prec SumPrec = 0, ProductPrec = 1, AtomPrec = 3;

struct SymbolEntry;

struct Factor {
    ex base;
    // A numeric, held as GiNaC's handle: copying a numeric value copies the whole object
    // (a tenth of decomposing a term). A symbolic power is its own base with exp 1.
    ex exp;
    bool negated = false;           // a sum shown with its signs flipped (see decompose)
    int power = 0;                  // exp when it is a small positive integer (most are 1 or 2), else 0
    SymbolEntry* symbol = nullptr;  // the base's entry, when it is a symbol (Builder::entry)
};

// coef · Π num / Π den, the factors in display order.
struct Decomposed {
    numeric coef{1};
    // coef while it is 1 or -1 by negations alone (the usual case), 0 once a number
    // multiplied it: its sign without cln comparing numbers.
    int unitSign = 1;
    std::vector<Factor> num, den;
};

struct TermKey {
    std::vector<int> velocities;  // indices of the velocity factors, with repetition
    int maxIndex = -1;            // of every other symbol
    bool trig = false;
    // The total degree: an integer while every factor's is a small integer; from the
    // first that is not (a square root, a float power) on, a number that every part is
    // added to in the factors' order, as the sum was always made (float sums depend on it).
    int wholeDegree = 0;
    std::optional<numeric> degreeSum;
    std::string text;  // Plain, without the coefficient
    void addDegree(int d) {
        if (degreeSum)
            *degreeSum += d;
        else
            wholeDegree += d;
    }
    void addDegree(const numeric& d) {
        if (!degreeSum && d.is_integer() && d.int_length() <= 20) {
            wholeDegree += d.to_int();
            return;
        }
        degreeSum = degreeSum ? *degreeSum + d : numeric(wholeDegree) + d;
    }
    numeric degree() const { return degreeSum ? *degreeSum : numeric(wholeDegree); }
};

// Display order of two terms by everything but their coefficients: <0, 0 or >0.
int compareKeys(const TermKey& a, const TermKey& b) {
    if (a.velocities != b.velocities) return a.velocities < b.velocities ? -1 : 1;
    if (a.maxIndex != b.maxIndex) return a.maxIndex < b.maxIndex ? -1 : 1;
    if (a.trig != b.trig) return a.trig ? 1 : -1;
    if (!a.degreeSum && !b.degreeSum) {
        if (a.wholeDegree != b.wholeDegree) return a.wholeDegree < b.wholeDegree ? -1 : 1;
    } else if (const numeric da = a.degree(), db = b.degree(); da != db) {
        return da < db ? -1 : 1;
    }
    return a.text.compare(b.text);
}

// A product term's factors in display order and its sort key, without the coefficient
// the sum gives it. A sum and its multiples share them: GiNaC writes ½ q̇2 c_12 as
// ½ q̇2 (2 c_12) with the ½ pulled out of every term, the rests unchanged.
struct TermBody {
    Decomposed d;  // d.coef: the rest's own sign (a negated sum factor's), not the term's
    TermKey key;
    int sign = 0;  // d.coef as 1 or -1 (0: another number), so a term's coefficient needs no product
};

struct Term {
    const TermBody* body;  // the number's is numberBody
    // The term's coefficient (the number itself), a numeric held as GiNaC's handle: most
    // are the sum's own pair coefficients, shared rather than copied.
    ex coef;
    DisplayPtr shown;      // |coefficient| times the factors, built once for every sign the sum shows with
    // The last tie-break of the order, made when two keys tie (seldom: only equal spellings).
    mutable std::optional<double> keyCoef;
    const numeric& value() const { return ex_to<numeric>(coef); }
    double tieBreak() const {
        if (!keyCoef) keyCoef = value().is_real() ? value().to_double() : 0.0;
        return *keyCoef;
    }
    bool negative() const { return value().is_real() && value().is_negative(); }
};

// A term of a sum as shown: its magnitude's node and its sign.
struct ShownTerm {
    DisplayPtr node;
    bool negative;
    bool more = false;  // "⋯ (N more terms)" of a cut sum: never negative
};

// A factor's place in a product: rank (number, constants, masses, parameters,
// coordinates, c/s, functions, sums, velocities), then indices, then the Plain spelling.
// The spelling of a sum or function is made only when rank and indices tie: a sum's is
// as long as the sum, and the expanded Panda's (C q̇)_i has tens of thousands of terms.
struct FactorKey {
    int rank = 0;
    std::vector<int> sub;
    mutable std::optional<std::string> text;  // a symbol's name at once; others when first needed
    ex base;                                  // what the text spells, and whether negated
    bool negated = false;
};

// What the builder keeps of a symbol (Builder::entry): its info, node and factor key,
// each made when first asked for.
struct SymbolEntry {
    ex held;  // the symbol
    const SymbolInfo* info = nullptr;
    DisplayPtr node;
    const FactorKey* key = nullptr;
    std::optional<std::string> text;  // its Plain spelling as a factor (a sort key's)
    struct Power {
        int exponent;
        DisplayPtr node;
        std::optional<std::string> text;  // Plain, as a factor
    };
    std::vector<Power> powers;  // its small powers shown: s2², q̇1²
    std::string name() const { return ex_to<GiNaC::symbol>(held).get_name(); }
};

// n == 1 as cln has it (a float 1.0 too), without cln converting every float to
// compare it with an integer: only a float whose double is 1 is compared exactly.
bool equalsOne(const numeric& n) {
    if (isSharedOne(n)) return true;  // often a pair's coefficient
    static const numeric unit(1);
    if (n.is_integer()) return n.is_equal(unit);
    return n.is_real() && !n.is_rational() && n.to_double() == 1.0 && n.is_equal(unit);
}

// Whether e is the number 1: mostly GiNaC's shared 1, a pointer compared.
bool isOne(const ex& e) {
    if (isSharedOne(ex_to<GiNaC::basic>(e))) return true;
    return ginacKind(e) == GinacKind::Numeric && equalsOne(ex_to<numeric>(e));
}

template <class T>
using ExMap = std::unordered_map<ex, T, std::hash<ex>, GiNaC::ex_is_equal>;

// A sum this long keeps its terms' bodies: one that comes back as a multiple of itself
// is ordered without decomposing its terms again. (Shorter ones cost little to redo.)
constexpr std::size_t keptBodiesFrom = 300;

class Builder {
public:
    explicit Builder(const DisplayOptions& o) : o_(o) { n_ = static_cast<int>(o.coordinateNames.size()); }

    DisplayPtr build(const ex& e) {
        if (is_a<GiNaC::matrix>(e)) {
            const GiNaC::matrix& m = ex_to<GiNaC::matrix>(e);
            auto node = std::make_shared<DisplayNode>();
            node->kind = DisplayKind::Matrix;
            node->rows.assign(m.rows(), std::vector<DisplayPtr>(m.cols()));
            for (unsigned i = 0; i < m.rows(); ++i)
                for (unsigned j = 0; j < m.cols(); ++j) node->rows[i][j] = render(m(i, j));
            return node;
        }
        return render(e);
    }

    DisplayPtr render(const ex& e) {
        const GinacKind kind = ginacKind(e);
        if (kind == GinacKind::Add) return renderSum(e, false);
        if (kind == GinacKind::Numeric) return renderNumber(ex_to<numeric>(e));
        if (kind == GinacKind::Symbol) return renderSymbol(ex_to<GiNaC::symbol>(e));
        if (kind == GinacKind::Other && (is_a<GiNaC::relational>(e) || is_a<GiNaC::lst>(e))) return renderAtom(e);
        Decomposed d = decompose(e);
        if (!d.coef.is_real() || !d.coef.is_negative()) return renderProduct(d);
        d.coef = -d.coef;
        d.unitSign = -d.unitSign;
        return negated(renderProduct(d));
    }

    const SymbolInfo& info(const GiNaC::symbol& s) { return info(entry(s)); }
    const SymbolInfo& info(SymbolEntry& e) {
        if (!e.info) e.info = &infoByName(e.name());
        return *e.info;
    }

    const SymbolInfo& infoByName(const std::string& name) {
        if (auto it = infos_.find(name); it != infos_.end()) return it->second;
        return infos_.emplace(name, computeInfo(name)).first->second;
    }

    SymbolInfo computeInfo(const std::string& name) {
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
        if (startsWith(name, "qdd") && allDigits(std::string_view(name).substr(3))) {  // accelerations: q̈1
            i.kind = Kind::Velocity;
            i.second = true;
            stem = i.base = "q" + name.substr(3);
        } else if (startsWith(name, "qd") && allDigits(std::string_view(name).substr(2))) {
            i.kind = Kind::Velocity;
            stem = i.base = "q" + name.substr(2);
        } else if (endsWith(name, "_dot") || endsWith(name, "_ddot")) {
            i.kind = Kind::Velocity;
            i.second = endsWith(name, "_ddot");
            stem = i.base = name.substr(0, name.size() - (i.second ? 5 : 4));
        } else if (isCoordinate(name)) {
            i.kind = Kind::Coordinate;
        } else if (name == "m" || (startsWith(name, "m") && (allDigits(std::string_view(name).substr(1)) || name[1] == '_'))) {
            i.kind = Kind::Mass;
        }
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

    // Drops what was kept of expressions (ordered sums, sort keys, shown powers and
    // atoms); keeps the symbols' nodes and keys and the numbers'.
    void forgetExpressions() {
        terms_.clear();
        bodies_.clear();
        for (auto& k : factorKeys_) k.clear();
        powers_.clear();
        atoms_.clear();
        for (auto& s : sums_) s.clear();
        factorTexts_.clear();
    }

private:
    const DisplayOptions& o_;
    int n_ = 0;
    // A symbol's info, node and factor key, by name (hashed; node-based: an element stays
    // in place while the map grows, so entries point at them), and by the symbol object
    // an expression holds (SymbolEntry).
    std::unordered_map<std::string, SymbolInfo> infos_;
    std::unordered_map<std::string, DisplayPtr> symbols_;
    std::unordered_map<std::string, FactorKey> symbolKeys_;
    std::unordered_map<const GiNaC::basic*, SymbolEntry> byObject_;
    std::unordered_map<std::string, SymbolEntry> unheld_;  // symbols no expression holds, by name

    SymbolEntry& unheld(const GiNaC::symbol& s) {
        auto [it, added] = unheld_.try_emplace(s.get_name());
        if (added) it->second.held = s;  // a copy: the entry's own
        return it->second;
    }
    ExMap<std::vector<ShownTerm>> terms_;
    ExMap<TermBody> bodies_;  // by a term's rest, for the terms of sums of keptBodiesFrom terms or more
    struct TermsScratch {  // terms()'s working vectors, one set per depth of nested sums
        std::vector<TermBody> local;
        std::vector<Term> out;
        std::vector<std::uint32_t> at;
    };
    std::vector<std::unique_ptr<TermsScratch>> scratch_;
    std::size_t depth_ = 0;
    ExMap<FactorKey> factorKeys_[2];  // by negated
    ExMap<std::vector<std::pair<numeric, DisplayPtr>>> powers_;  // base^exponent, shown
    ExMap<DisplayPtr> atoms_;
    ExMap<DisplayPtr> sums_[2];  // by negate
    std::unordered_map<const DisplayNode*, std::pair<DisplayPtr, std::string>> factorTexts_;
    std::unordered_map<std::uint64_t, DisplayPtr> decimals_;  // a float's node, by its bits
    std::unordered_map<long, DisplayPtr> integers_;      // a machine integer's node
    std::map<std::pair<long, long>, DisplayPtr> fractions_;  // a fraction of machine integers' node
    const GiNaC::basic* decimalSum_ = nullptr;             // the sum buildReadable shows with readable coefficients
    std::vector<ShownTerm> decimalTerms_;                  // its terms (not cached by the sum)
    ExMap<ex> readable_;                              // readableCoefficient's, fractions only

    bool isCoordinate(const std::string& name) const {
        if (o_.coordinateNames.empty()) return startsWith(name, "q") && allDigits(std::string_view(name).substr(1));
        return std::find(o_.coordinateNames.begin(), o_.coordinateNames.end(), name) != o_.coordinateNames.end();
    }

    static DisplayPtr negated(DisplayPtr magnitude) {
        auto n = std::make_shared<DisplayNode>();
        n->kind = DisplayKind::Sum;
        n->children = {std::move(magnitude)};
        n->negative = {true};
        return n;
    }

    static std::string keyText(const DisplayNode& n) { return renderDisplay(n, DisplayStyle::Plain, true); }

    // ---- order

    // The terms of a sum in display order (cached: a sum factor is ordered once). Only
    // each term's node and sign are kept; the bodies that ordered them only for sums
    // long enough to come back as a multiple (the expanded Panda's (C q̇)_i): the rest
    // are freed at once, and their memory serves the next sum.
    const std::vector<ShownTerm>& terms(const ex& sum) {
        const bool decimal = isDecimalSum(sum);
        if (!decimal)
            if (auto it = terms_.find(sum); it != terms_.end()) return it->second;
        const GiNaC::add& terms = ex_to<GiNaC::add>(sum);
        const GiNaC::epvector& pairs = GinacPairs::of(terms);
        const bool keep = pairs.size() >= keptBodiesFrom;
        // This call's working vectors, reused by the next sum ordered at the same depth
        // (a sum factor's terms are ordered inside its term's): their own memory was
        // four allocations and frees per sum.
        if (scratch_.size() <= depth_) scratch_.push_back(std::make_unique<TermsScratch>());
        TermsScratch& scratch = *scratch_[depth_];
        struct Level {  // the depth back, the terms emptied (the vectors' memory kept)
            std::size_t& depth;
            TermsScratch& scratch;
            ~Level() {
                --depth;
                scratch.out.clear();  // (the bodies stay for the next sum: bodyInto empties each)
            }
        } level{++depth_, scratch};
        // Bodies from earlier sums are reused (bodyInto); sized before the terms point
        // into it, so never reallocated while they do.
        std::vector<TermBody>& local = scratch.local;
        if (!keep && local.size() < pairs.size()) local.resize(pairs.size());
        std::size_t used = 0;
        std::vector<Term>& out = scratch.out;
        out.reserve(pairs.size() + 1);
        // The (rest, coefficient) pairs in place, in op()'s order, then the number: op(i)
        // would make a product rest·coefficient for every term (core/symbolic/ginac_pairs).
        for (const GiNaC::expair& p : pairs) {
            const TermBody* body = nullptr;
            if (keep) {
                auto it = bodies_.find(p.rest);  // (bodyOf may add to bodies_: made before emplacing)
                if (it == bodies_.end()) it = bodies_.emplace(p.rest, bodyOf(p.rest)).first;
                body = &it->second;
            } else {
                TermBody& reused = local[used++];
                bodyInto(p.rest, reused);
                body = &reused;
            }
            const ex& k = decimal ? readableCoefficient(p.coeff) : p.coeff;
            out.push_back({body,
                           body->sign == 1    ? k
                           : body->sign == -1 ? ex(-ex_to<numeric>(k))
                                              : ex(body->d.coef * ex_to<numeric>(k)),
                           nullptr, std::nullopt});
        }
        if (const ex& number = GinacPairs::number(terms); !number.is_zero()) {
            const ex& n = decimal ? readableCoefficient(number) : number;
            out.push_back({&numberBody(), n, renderNumber(abs(ex_to<numeric>(n))), std::nullopt});
        }
        // Indices sorted, then each term's node taken once.
        std::vector<std::uint32_t>& at = scratch.at;
        at.resize(out.size());
        for (std::uint32_t i = 0; i < at.size(); ++i) at[i] = i;
        std::stable_sort(at.begin(), at.end(), [&](std::uint32_t a, std::uint32_t b) {
            const Term &x = out[a], &y = out[b];
            const int c = x.body == y.body ? 0 : compareKeys(x.body->key, y.body->key);
            return c != 0 ? c < 0 : x.tieBreak() < y.tieBreak();
        });
        // Each shown term's node built once it is known to be shown (a cut sum for pages
        // leaves most of them out).
        const bool cut = o_.cutLongSums && out.size() > maxTypesetTerms;
        const std::size_t shown = cut ? keptTypesetTerms : out.size();
        std::vector<ShownTerm> sorted;
        sorted.reserve(shown + 1);
        for (std::size_t k = 0; k < shown; ++k) {
            Term& t = out[at[k]];
            if (!t.shown) {  // |coefficient|: the coefficient itself unless it is negative
                const numeric& v = t.value();
                t.shown = v.is_real() && v.is_negative() ? withCoefficient(-v, t.body->d) : withCoefficient(v, t.body->d);
            }
            sorted.push_back({std::move(t.shown), t.negative()});
        }
        if (cut) sorted.push_back({displayMoreTerms(out.size() - shown), false, true});
        if (decimal) return decimalTerms_ = std::move(sorted);
        return terms_.emplace(sum, std::move(sorted)).first->second;
    }

    static const TermBody& numberBody() {
        static const TermBody body{{}, {{}, -1, false, 0, std::nullopt, "1"}, 1};
        return body;
    }

    TermBody bodyOf(const ex& rest) {
        TermBody b;
        bodyInto(rest, b);
        return b;
    }

    // b may hold an earlier term's body (terms()'s working bodies): emptied, its vectors'
    // and key text's memory reused.
    void bodyInto(const ex& rest, TermBody& b) {
        static const numeric unit(1), minusUnit(-1);
        b.d.coef = unit;
        b.d.unitSign = 1;
        b.d.num.clear();
        b.d.den.clear();
        TermKey& k = b.key;
        k.velocities.clear();
        k.maxIndex = -1;
        k.trig = false;
        k.wholeDegree = 0;
        k.degreeSum.reset();
        decomposeInto(rest, b.d);
        // From the factors, not the term: walking a GiNaC product makes each power anew.
        for (const Factor& f : b.d.num) {
            if (f.symbol) {  // most factors: looked up once, degree 1
                const SymbolInfo& i = info(*f.symbol);
                if (i.kind == Kind::Velocity && f.power > 0)
                    k.velocities.insert(k.velocities.end(), f.power, i.indices.empty() ? 0 : i.indices.back());
                note(i, k);
                if (f.power > 0)
                    k.addDegree(f.power);
                else
                    k.addDegree(ex_to<numeric>(f.exp));
                continue;
            }
            scan(f.base, k);
            k.addDegree(degree(f.base) * ex_to<numeric>(f.exp));
        }
        for (const Factor& f : b.d.den) {
            scan(f.base, k);
            k.addDegree(-degree(f.base) * ex_to<numeric>(f.exp));
        }
        std::sort(k.velocities.begin(), k.velocities.end());
        bodyKeyText(b.d, k.text);
        b.sign = b.d.unitSign != 0           ? b.d.unitSign
                 : !b.d.coef.is_integer()    ? 0
                 : b.d.coef.is_equal(unit)   ? 1
                 : b.d.coef.is_equal(minusUnit) ? -1
                                             : 0;
    }

    // The Plain spelling (with c/s names) of the term without its coefficient, as
    // renderDisplay prints the product of its factors: the order's last tie-break. Made
    // from the factors' spellings, which recur in thousands of terms, without building
    // the product.
    void bodyKeyText(const Decomposed& d, std::string& s) {
        s.clear();
        if (!d.den.empty()) {
            s = keyText(*renderProduct(d, false));
            return;
        }
        if (d.num.empty()) {
            s = "1";
            return;
        }
        for (const Factor& f : d.num) {
            if (!s.empty()) s += '*';
            if (f.symbol && f.power == 1) {  // most factors
                s += symbolText(*f.symbol);
                continue;
            }
            if (f.symbol && f.power > 1) {
                SymbolEntry::Power& p = symbolPower(f);
                if (!p.text) p.text = keyText(*p.node);
                s += *p.text;
                continue;
            }
            s += factorText(renderFactor(f));
        }
    }

    // A symbol's spelling as a factor (kept with the symbol, not per expression).
    const std::string& symbolText(SymbolEntry& e) {
        if (!e.text) e.text = keyText(*renderSymbol(e));
        return *e.text;
    }

    // (Cached by node; the cache holds the node, so its address is not reused.)
    const std::string& factorText(const DisplayPtr& node) {
        auto [it, added] = factorTexts_.try_emplace(node.get());
        if (added) it->second = {node, keyText(*node)};
        return it->second.second;
    }

    // What a symbol adds to a key: whether it is a c/s, and its index unless a velocity's.
    static void note(const SymbolInfo& i, TermKey& k) {
        if (i.kind == Kind::Trig) k.trig = true;
        if (i.kind != Kind::Velocity && !i.indices.empty())
            k.maxIndex = std::max(k.maxIndex, *std::max_element(i.indices.begin(), i.indices.end()));
    }

    // What the symbols and functions anywhere in e add to a key (ginac_pairs.hpp's walk).
    void scan(const ex& e, TermKey& k) {
        auto visit = [&](const ex& node, GinacKind kind) {
            if (kind == GinacKind::Symbol) note(info(ex_to<GiNaC::symbol>(node)), k);
            if (kind == GinacKind::Function) {
                const std::string& name = ex_to<GiNaC::function>(node).get_name();
                if (name == "sin" || name == "cos" || name == "tan") k.trig = true;
            }
            return false;
        };
        anyNode(e, visit);
    }

    static numeric degree(const ex& e) {
        if (isKind(e, GinacKind::Numeric) || isKind(e, GinacKind::Constant)) return 0;
        if (isKind(e, GinacKind::Add)) {
            numeric d = 0;
            for (const ex& t : e)
                if (const numeric dt = degree(t); d < dt) d = dt;
            return d;
        }
        if (isKind(e, GinacKind::Mul)) {
            numeric d = 0;
            for (const ex& f : e) d += degree(f);
            return d;
        }
        if (isKind(e, GinacKind::Power) && isKind(e.op(1), GinacKind::Numeric) && ex_to<numeric>(e.op(1)).is_real())
            return degree(e.op(0)) * ex_to<numeric>(e.op(1));
        return 1;
    }

    // GiNaC gives a sum factor with an integer power the sign that makes its leading
    // term positive in GiNaC's hash order, which varies: (b−a)² or (a−b)². Shown here
    // with the leading term in *our* order positive, an odd power's sign moved to coef.
    Decomposed decompose(const ex& e) {
        Decomposed d;
        decomposeInto(e, d);
        return d;
    }

    // Into an empty d (its vectors' memory may be an earlier term's).
    void decomposeInto(const ex& e, Decomposed& d) {
        auto factor = [&](Factor f) {
            const numeric* k = &ex_to<numeric>(f.exp);
            if (isKind(f.base, GinacKind::Add) && k->is_integer() && terms(f.base).front().negative) {
                f.negated = true;
                if (k->is_odd()) {
                    d.coef = -d.coef;
                    d.unitSign = -d.unitSign;
                }
            }
            if (isKind(f.base, GinacKind::Symbol)) f.symbol = &entry(ex_to<GiNaC::symbol>(f.base));
            const bool below = k->is_negative();
            if (below) {
                f.exp = -*k;
                k = &ex_to<numeric>(f.exp);
            }
            if (k->is_pos_integer() && k->int_length() <= 20) f.power = k->to_int();
            (below ? d.den : d.num).push_back(std::move(f));
        };
        auto one = [&](const ex& x) {
            if (isKind(x, GinacKind::Numeric)) {
                d.coef *= ex_to<numeric>(x);
                d.unitSign = 0;
            } else if (isKind(x, GinacKind::Power) && isKind(x.op(1), GinacKind::Numeric) && ex_to<numeric>(x.op(1)).is_real()) {
                factor({x.op(0), x.op(1)});
            } else {
                factor({x, ex(1)});
            }
        };
        if (isKind(e, GinacKind::Mul)) {
            // Its (base, exponent) pairs in place, in op()'s order, then its coefficient.
            const GiNaC::epvector& pairs = GinacPairs::of(ex_to<GiNaC::mul>(e));
            d.num.reserve(pairs.size());  // grown one factor at a time, a term allocated four times
            for (const GiNaC::expair& p : pairs) {
                const numeric& k = ex_to<numeric>(p.coeff);
                const bool once = isOne(p.coeff);
                if (once && isKind(p.rest, GinacKind::Symbol)) {  // most factors: a symbol to the first power
                    Factor& f = d.num.emplace_back(Factor{p.rest, p.coeff});
                    f.power = 1;
                    f.symbol = &entry(ex_to<GiNaC::symbol>(p.rest));
                } else if (once || !k.is_real()) {
                    one(once ? p.rest : GiNaC::pow(p.rest, p.coeff));  // as op() gives it
                } else {
                    factor({p.rest, p.coeff});
                }
            }
            if (const ex& c = GinacPairs::number(ex_to<GiNaC::mul>(e)); !isOne(c)) {
                d.coef *= ex_to<numeric>(c);
                d.unitSign = 0;
            }
        } else {
            one(e);
        }
        auto order = [this](std::vector<Factor>& fs) {
            if (fs.size() < 2) return;
            // Sorted by pointers to the cached keys: a key holds a vector and a string,
            // and copying them for every factor of every term was a tenth of the printing.
            // A term has a handful of factors: an insertion sort (stable, as only a
            // smaller key moves a factor forward) needs no buffer, stable_sort allocates one.
            constexpr std::size_t onStack = 32;
            if (fs.size() <= onStack) {
                const FactorKey* keys[onStack];
                for (std::size_t i = 0; i < fs.size(); ++i) keys[i] = &factorKey(fs[i]);
                for (std::size_t i = 1; i < fs.size(); ++i)
                    for (std::size_t j = i; j > 0 && less(*keys[j], *keys[j - 1]); --j) {
                        std::swap(keys[j], keys[j - 1]);
                        std::swap(fs[j], fs[j - 1]);
                    }
                return;
            }
            std::vector<std::pair<const FactorKey*, Factor>> k;
            k.reserve(fs.size());
            for (Factor& f : fs) k.emplace_back(&factorKey(f), std::move(f));
            std::stable_sort(k.begin(), k.end(), [this](const auto& a, const auto& b) { return less(*a.first, *b.first); });
            for (std::size_t i = 0; i < fs.size(); ++i) fs[i] = std::move(k[i].second);
        };
        order(d.num);
        order(d.den);
    }

    // Number, constants, masses, parameters, coordinates, c/s, functions, sums, velocities.
    // (A reference into a cache: node-based maps keep their elements in place.)
    const FactorKey& factorKey(const Factor& f) {
        const ex& b = f.base;
        if (f.symbol) {
            SymbolEntry& e = *f.symbol;
            if (e.key) return *e.key;
            const std::string name = e.name();
            if (auto it = symbolKeys_.find(name); it != symbolKeys_.end()) return *(e.key = &it->second);
            const SymbolInfo& i = info(e);
            static const int rank[] = {1, 2, 3, 4, 7};  // by Kind; functions 5, sums 6
            std::vector<int> sub = i.indices.empty() ? std::vector<int>{INT_MAX} : i.indices;
            if (i.trig) sub.push_back(i.trig->kind == 'c' ? 0 : 1);  // c1 before s1
            return *(e.key = &(symbolKeys_[name] = FactorKey{rank[static_cast<int>(i.kind)], sub, name, b, false}));
        }
        ExMap<FactorKey>& cache = factorKeys_[f.negated ? 1 : 0];
        if (auto it = cache.find(b); it != cache.end()) return it->second;
        const int rank = isKind(b, GinacKind::Numeric) || isKind(b, GinacKind::Constant) ? 0 : isKind(b, GinacKind::Function) ? 5 : 6;
        return cache.emplace(b, FactorKey{rank, {}, std::nullopt, b, f.negated}).first->second;
    }

    bool less(const FactorKey& a, const FactorKey& b) {
        if (a.rank != b.rank) return a.rank < b.rank;
        if (a.sub != b.sub) return a.sub < b.sub;
        return spelling(a) < spelling(b);
    }

    const std::string& spelling(const FactorKey& k) {
        if (!k.text) k.text = keyText(*(isKind(k.base, GinacKind::Add) ? renderSum(k.base, k.negated) : render(k.base)));
        return *k.text;
    }

    // ---- sums

    // (Cached: JSON shows B, C, g again beside the steps, and a sum factor's sort key
    // renders the sum it then shows.)
    DisplayPtr renderSum(const ex& e, bool negate) {
        ExMap<DisplayPtr>& cache = sums_[negate ? 1 : 0];
        const bool decimal = isDecimalSum(e);
        if (!decimal)
            if (auto it = cache.find(e); it != cache.end()) return it->second;
        auto n = std::make_shared<DisplayNode>();
        n->kind = DisplayKind::Sum;
        const std::vector<ShownTerm>& ts = terms(e);
        n->children.reserve(ts.size());
        n->negative.reserve(ts.size());
        for (const ShownTerm& t : ts) {
            n->negative.push_back(!t.more && t.negative != negate);
            n->children.push_back(t.node);
        }
        if (decimal) return n;
        return cache.emplace(e, std::move(n)).first->second;
    }

    // ---- readable numbers (core/symbolic/readable_numbers.hpp)

public:
    // e as readableNumbers(e) shows. When only a sum's coefficients change (a named
    // quantity's or an expanded entry's), they are read as readableNumber gives them
    // while the sum is ordered, and the sum is not rebuilt with them; it is then not
    // cached, as the same sum elsewhere shows its exact numbers.
    DisplayPtr buildReadable(const ex& e) {
        switch (readableChange(e)) {
            case ReadableChange::None: return build(e);
            case ReadableChange::Everywhere: return build(readableNumbers(e));
            case ReadableChange::Coefficients: break;
        }
        struct Reset {  // also when ordering throws (a cancel)
            const GiNaC::basic*& sum;
            ~Reset() { sum = nullptr; }
        } reset{decimalSum_};
        decimalSum_ = &ex_to<GiNaC::basic>(e);
        return renderSum(e, false);
    }

private:

    bool isDecimalSum(const ex& e) const { return decimalSum_ == &ex_to<GiNaC::basic>(e); }

    // A coefficient as readableNumber makes it (each value once: they recur).
    // (Only fractions are kept: the cache's equality has 2 == 2.0, and only a fraction
    // changes. A float or an integer is its own readable number.)
    const ex& readableCoefficient(const ex& k) {
        const numeric& n = ex_to<numeric>(k);
        if (n.is_integer() || !n.is_rational()) return k;
        auto [it, added] = readable_.try_emplace(k);
        if (added) it->second = readableNumber(n);
        return it->second;
    }

    // ---- numbers

    DisplayPtr renderNumber(const numeric& n) {
        if (!n.is_real()) {  // not expected in mechanics; GiNaC's form, parenthesised
            std::ostringstream plain, latex;
            plain << n;
            latex << GiNaC::latex << n;
            return displayRaw("(" + plain.str() + ")", "(" + latex.str() + ")", "(" + plain.str() + ")");
        }
        if (n.is_negative()) return negated(renderNumber(-n));
        // Coefficients recur (C is made of B's, the equations of both): each is built once.
        if (n.is_integer()) {
            const bool small = n.int_length() < 63;
            if (small)
                if (auto it = integers_.find(n.to_long()); it != integers_.end()) return it->second;
            const std::string s = str(n);
            DisplayPtr node = displayNumber(s, s, s);
            if (small) integers_.emplace(n.to_long(), node);
            return node;
        }
        if (n.is_rational()) {
            const numeric numer = n.numer(), denom = n.denom();
            if (numer.int_length() >= 63 || denom.int_length() >= 63)
                return displayNode(DisplayKind::Fraction, {renderNumber(numer), renderNumber(denom)});
            const std::pair<long, long> key{numer.to_long(), denom.to_long()};  // ½ in every c_ij: built once
            if (auto it = fractions_.find(key); it != fractions_.end()) return it->second;
            return fractions_[key] = displayNode(DisplayKind::Fraction, {renderNumber(numer), renderNumber(denom)});
        }
        const double v = n.to_double();
        const auto bits = std::bit_cast<std::uint64_t>(v);
        if (auto it = decimals_.find(bits); it != decimals_.end()) return it->second;
        return decimals_[bits] = decimalNode(v);
    }

    static DisplayPtr decimalNode(double v) {
        const std::string s = readable(v), plain = seventeen(v);
        const auto e = s.find('e');
        if (e == std::string::npos) return displayNumber(s, s, plain);
        const std::string mantissa = s.substr(0, e), exponent = std::to_string(std::stoi(s.substr(e + 1)));
        return displayNumber(mantissa, mantissa, plain, exponent);
    }

    // ---- atoms

    DisplayPtr renderSymbol(const GiNaC::symbol& sym) { return renderSymbol(entry(sym)); }
    DisplayPtr renderSymbol(SymbolEntry& e) {
        if (!e.node) e.node = namedNode(e);
        return e.node;
    }

    // A symbol's entry by the object an expression holds: GiNaC shares one object among
    // all the copies of an expression that name the symbol, so most lookups are one
    // pointer hashed, with no name copied (get_name returns a copy) or compared. The
    // entry holds the object, so its address is not reused while the entry lives. A
    // symbol no expression holds (on the stack) has its entry by name.
    SymbolEntry& entry(const GiNaC::symbol& s) {
        if (s.get_refcount() == 0) return unheld(s);
        auto [it, added] = byObject_.try_emplace(&s);
        if (added) {
            it->second.held = s;  // on the heap (counted), so shared, not copied
            if (&ex_to<GiNaC::basic>(it->second.held) != &s) {  // copied after all: not cached
                byObject_.erase(it);
                return unheld(s);
            }
        }
        return it->second;
    }

    DisplayPtr namedNode(SymbolEntry& e) {
        const std::string name = e.name();
        if (auto it = symbols_.find(name); it != symbols_.end()) return it->second;
        if (o_.givenSymbols)
            if (auto it = o_.givenSymbols->find(name); it != o_.givenSymbols->end()) return symbols_[name] = it->second;
        const SymbolInfo& i = info(e);
        std::shared_ptr<DisplayNode> n;
        if (i.kind == Kind::Trig) {
            n = std::make_shared<DisplayNode>();
            n->kind = DisplayKind::Symbol;
            n->name = name;
            std::string arg;
            for (int k : i.indices)
                arg += (arg.empty() ? "" : "+") + (k <= n_ ? o_.coordinateNames[k - 1] : "q" + std::to_string(k));
            n->plain = (i.trig->kind == 'c' ? "cos(" : "sin(") + arg + ")";
            const bool joined = name.find('_') != std::string::npos;
            std::string sub;
            for (int k : i.indices) sub += (sub.empty() || !joined ? "" : ",") + std::to_string(k);
            n->text = n->latex = std::string(1, i.trig->kind);
            n->subText = n->subLatex = n->subShown = sub;
        } else if (i.kind == Kind::Velocity) {
            n = namedSymbol(i.base, textName(i.base));
            n->name = n->plain = name;
            n->dots = i.second ? 2 : 1;
        } else {
            n = namedSymbol(name, textName(name));
        }
        return symbols_[name] = n;
    }

    DisplayPtr renderConstant(const ex& c) {
        std::ostringstream plain;
        plain << c;
        const std::string name = plain.str();
        auto n = std::make_shared<DisplayNode>();
        n->kind = DisplayKind::Symbol;
        n->name = n->plain = name;
        if (name == "Pi") {
            n->text = "π";
            n->latex = "\\pi";
        } else if (name == "Euler") {
            n->text = "γ";
            n->latex = "\\gamma";
        } else {
            n->text = name;
            n->latex = "\\mathrm{" + name + "}";
            n->upright = true;
        }
        return n;
    }

    DisplayPtr renderFunction(const ex& f) {
        static const std::map<std::string, std::string> known = {
            {"sin", "\\sin"},     {"cos", "\\cos"},     {"tan", "\\tan"},   {"exp", "\\exp"},
            {"log", "\\ln"},      {"sinh", "\\sinh"},   {"cosh", "\\cosh"}, {"tanh", "\\tanh"},
            {"asin", "\\arcsin"}, {"acos", "\\arccos"}, {"atan", "\\arctan"}};
        const std::string name = ex_to<GiNaC::function>(f).get_name();
        auto n = std::make_shared<DisplayNode>();
        n->kind = DisplayKind::Function;
        n->text = n->plain = n->name = name;
        const auto it = known.find(name);
        n->latex = it != known.end() ? it->second : "\\operatorname{" + latexEscape(name) + "}";
        n->upright = true;
        for (const ex& a : f) n->children.push_back(render(a));
        return n;
    }

    DisplayPtr renderRelational(const GiNaC::relational& r) {
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
        auto n = std::make_shared<DisplayNode>();
        n->kind = DisplayKind::Equation;
        n->children = {render(r.lhs()), render(r.rhs())};
        n->plain = op->plain;
        n->text = std::string(" ") + op->text + " ";
        n->latex = std::string(" ") + op->latex + " ";
        return n;
    }

    DisplayPtr renderAtom(const ex& e) {
        if (isKind(e, GinacKind::Symbol)) return renderSymbol(ex_to<GiNaC::symbol>(e));
        if (isKind(e, GinacKind::Numeric)) return renderNumber(ex_to<numeric>(e));
        if (auto it = atoms_.find(e); it != atoms_.end()) return it->second;
        DisplayPtr out;
        if (isKind(e, GinacKind::Constant)) {
            out = renderConstant(e);
        } else if (isKind(e, GinacKind::Function)) {
            out = renderFunction(e);
        } else if (isKind(e, GinacKind::Add)) {
            out = renderSum(e, false);
        } else if (isKind(e, GinacKind::Power)) {  // symbolic exponent
            out = displayNode(DisplayKind::Power, {fenced(render(e.op(0)), AtomPrec), render(e.op(1))});
        } else if (isKind(e, GinacKind::Mul)) {
            out = render(e);
        } else if (is_a<GiNaC::relational>(e)) {
            out = renderRelational(ex_to<GiNaC::relational>(e));
        } else if (is_a<GiNaC::lst>(e)) {
            std::vector<DisplayPtr> items;
            for (const ex& item : e) items.push_back(render(item));
            out = displayNode(DisplayKind::List, std::move(items));
        } else {
            std::ostringstream plain, latex;  // other GiNaC classes: its own printer
            plain << e;
            latex << GiNaC::latex << e;
            out = displayRaw("(" + plain.str() + ")", "(" + latex.str() + ")", "(" + plain.str() + ")");
        }
        return atoms_.emplace(e, out).first->second;
    }

    // x in parentheses when its precedence is below `atLeast`.
    static DisplayPtr fenced(DisplayPtr x, Prec atLeast) {
        if (displayPrecedence(*x) >= atLeast) return x;
        return displayNode(DisplayKind::Fence, {std::move(x)});
    }

    // ---- products

    DisplayPtr renderFactor(const Factor& f) {
        const numeric& k = ex_to<numeric>(f.exp);
        if (f.negated || f.power == 1) {
            const DisplayPtr b = f.negated ? renderSum(f.base, true) : f.symbol ? renderSymbol(*f.symbol) : renderAtom(f.base);
            if (f.power == 1) return fenced(b, ProductPrec + 1);
            return power(b, f);
        }
        // The same powers (c2², q̇1²) recur in thousands of terms: each is built once, a
        // symbol's small powers once for the builder, others once per expression.
        if (f.symbol && f.power > 1) return symbolPower(f).node;
        std::vector<std::pair<numeric, DisplayPtr>>& shown = powers_[f.base];
        for (const auto& [exponent, node] : shown)
            if (exponent == k) return node;
        DisplayPtr node = power(f.symbol ? renderSymbol(*f.symbol) : renderAtom(f.base), f);
        shown.emplace_back(k, node);
        return node;
    }

    // A symbol's small power f (kept with the symbol).
    SymbolEntry::Power& symbolPower(const Factor& f) {
        for (SymbolEntry::Power& p : f.symbol->powers)
            if (p.exponent == f.power) return p;
        return f.symbol->powers.emplace_back(SymbolEntry::Power{f.power, power(renderSymbol(*f.symbol), f), std::nullopt});
    }

    DisplayPtr power(const DisplayPtr& b, const Factor& f) {
        const numeric& k = ex_to<numeric>(f.exp);
        if (k == numeric(1, 2)) return displayNode(DisplayKind::Root, {b});
        const std::string power = str(k);
        DisplayPtr exponent;
        if (k.is_integer() || k.is_rational())
            exponent = displayNumber(power, power, power);
        else
            exponent = displayNumber(power, power, seventeen(k.to_double()));
        const bool function = isKind(f.base, GinacKind::Function);
        return displayNode(DisplayKind::Power, {function ? b : fenced(b, AtomPrec), exponent});
    }

    static DisplayPtr productOf(std::vector<DisplayPtr> pieces) {
        if (pieces.empty()) return displayNumber("1", "1", "1");
        if (pieces.size() == 1) return pieces[0];
        return displayNode(DisplayKind::Product, std::move(pieces));
    }

    // The product as decomposed (its sign is the caller's: coef ≥ 0 here).
    DisplayPtr renderProduct(const Decomposed& d, bool withCoef = true) {
        return withCoefficient(withCoef ? d.coef : numeric(1), d);
    }

    // c times the product of d's factors.
    DisplayPtr withCoefficient(const numeric& c, const Decomposed& d) {
        std::vector<DisplayPtr> num, den;
        num.reserve(d.num.size() + 1);
        if (d.den.empty() || !c.is_rational()) {
            if (!equalsOne(c)) num.push_back(renderNumber(c));  // 2, 1/2, 0.5 in front
        } else {
            if (c.numer() != 1) num.push_back(renderNumber(c.numer()));
            if (c.denom() != 1) den.push_back(renderNumber(c.denom()));
        }
        for (const Factor& f : d.num) num.push_back(renderFactor(f));
        for (const Factor& f : d.den) den.push_back(renderFactor(f));
        if (den.empty()) return productOf(std::move(num));
        return displayNode(DisplayKind::Fraction, {productOf(std::move(num)), productOf(std::move(den))});
    }
};

}  // namespace

struct DisplayBuilder::Impl {
    DisplayOptions options;
    Builder builder;
    DisplayBuilder::Sharing sharing;
    Impl(const DisplayOptions& o, DisplayBuilder::Sharing s) : options(o), builder(options), sharing(s) {}

    // What build() shows; a Sharing::Symbols builder then forgets the expression's caches
    // (also when showing it throws).
    template <class Build>
    DisplayPtr shown(Build build) {
        struct Forget {
            Impl& impl;
            ~Forget() {
                if (impl.sharing == DisplayBuilder::Sharing::Symbols) impl.builder.forgetExpressions();
            }
        } forget{*this};
        return build();
    }
};

DisplayBuilder::DisplayBuilder(const DisplayOptions& options, Sharing sharing) : impl_(new Impl(options, sharing)) {}
DisplayBuilder::~DisplayBuilder() { delete impl_; }
DisplayPtr DisplayBuilder::operator()(const ex& e) {
    return impl_->shown([&] { return impl_->builder.build(e); });
}

DisplayPtr DisplayBuilder::readable(const ex& e) {
    return impl_->shown([&] { return impl_->builder.buildReadable(e); });
}

DisplayPtr buildDisplay(const ex& e, const DisplayOptions& options) { return Builder(options).build(e); }

// The content of the braces that open at `at` ({...}), advancing `at` past them.
std::string braced(const std::string& s, std::size_t& at) {
    if (at >= s.size() || s[at] != '{') {  // a single character: x_1
        return at < s.size() ? std::string(1, s[at++]) : std::string();
    }
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
    for (const char* accent : {"\\dot{", "\\ddot{"}) {
        for (std::size_t at; (at = latex.find(accent)) != std::string::npos;) {
            std::size_t open = at + std::string(accent).size() - 1;
            const std::string inner = braced(latex, open);
            const bool two = std::string(accent) == "\\ddot{";
            std::string shown = shownFromLatex(inner);
            std::size_t first = 1;
            while (first < shown.size() && (static_cast<unsigned char>(shown[first]) & 0xC0) == 0x80) ++first;
            shown = shown.substr(0, first) + (two ? "\u0308" : "\u0307") + shown.substr(first);
            latex.replace(at, open - at, shown);
        }
    }
    return shownFromLatex(latex);
}

DisplayPtr displayLabel(const std::string& name, const std::string& latexName, const DisplayOptions&) {
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
    if (head.find("\\frac") != std::string::npos || head.find("\\text") != std::string::npos || at < latexName.size()) {
        shown->text = name;
        shown->upright = true;
    } else {
        bool upright = false;
        shown->text = shownLabelPart(head);
        shown->subShown = shownLabelPart(sub);
        shown->subUpright = sub.find("\\mathrm") != std::string::npos;
        shown->supText = shownLabelPart(sup);
        (void)upright;
    }
    n->children = {shown};
    return n;
}

DisplayPtr displaySymbolName(const std::string& name, int dots) {
    auto n = namedSymbol(name, textName(name));
    n->dots = dots;
    return n;
}

DisplayPtr displaySumOf(const std::vector<DisplayPtr>& parts) {
    auto n = std::make_shared<DisplayNode>();
    n->kind = DisplayKind::Sum;
    // Parts built for pages may be cut already ("⋯ (N more terms)" last: cutLongSums).
    // Joined, the whole is cut as the typesetter cuts the sum of every term: its first
    // keptTypesetTerms, then the count of the rest. (A cut part shows its first
    // keptTypesetTerms terms, so those are always among the shown ones.)
    std::size_t total = 0;
    bool cut = false;
    for (const DisplayPtr& p : parts) {
        const std::size_t more = p->kind == DisplayKind::Sum && !p->children.empty() ? moreTermsCount(*p->children.back()) : 0;
        cut = cut || more > 0;
        total += p->kind != DisplayKind::Sum ? 1 : more > 0 ? p->children.size() - 1 + more : p->children.size();
    }
    if (cut) {
        for (const DisplayPtr& p : parts) {
            const std::size_t shown = p->kind == DisplayKind::Sum ? p->children.size() : 1;
            for (std::size_t i = 0; i < shown && n->children.size() < keptTypesetTerms; ++i) {
                const DisplayPtr& term = p->kind == DisplayKind::Sum ? p->children[i] : p;
                if (moreTermsCount(*term)) break;
                n->children.push_back(term);
                n->negative.push_back(p->kind == DisplayKind::Sum && p->negative[i]);
            }
        }
        n->children.push_back(displayMoreTerms(total - n->children.size()));
        n->negative.push_back(false);
        return n;
    }
    for (const DisplayPtr& p : parts) {
        if (p->kind == DisplayKind::Sum) {
            n->children.insert(n->children.end(), p->children.begin(), p->children.end());
            n->negative.insert(n->negative.end(), p->negative.begin(), p->negative.end());
        } else {
            n->children.push_back(p);
            n->negative.push_back(false);
        }
    }
    if (n->children.empty()) return displayNumber("0", "0", "0");
    return n;
}

}  // namespace ll::symbolic
