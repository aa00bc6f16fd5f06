#include "core/present/display_builder.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <sstream>

#include "core/present/number_spelling.hpp"

namespace ll::present {

using GiNaC::ex, GiNaC::ex_to, GiNaC::is_a, GiNaC::numeric;

namespace {

constexpr int productPrecedence = 1, atomPrecedence = 3;  // displayPrecedence's

// x in parentheses when its precedence is below `atLeast`.
DisplayPtr fenced(DisplayPtr x, int atLeast) {
    if (displayPrecedence(*x) >= atLeast) return x;
    return displayNode(DisplayKind::Fence, {std::move(x)});
}

DisplayPtr productOf(std::vector<DisplayPtr> pieces) {
    if (pieces.empty()) return displayNumber("1", "1", "1");
    if (pieces.size() == 1) return pieces[0];
    return displayNode(DisplayKind::Product, std::move(pieces));
}

bool isOne(const numeric& n) { return n.is_equal(numeric(1)); }

// The Plain spelling with c/s names: what the orders compare.
std::string keyText(const DisplayNode& n) { return renderDisplay(n, DisplayStyle::Plain, true); }

// The total degree of e in its symbols (and functions), as a term's key counts it.
numeric degreeOf(const ex& e) {
    if (is_a<numeric>(e) || is_a<GiNaC::constant>(e)) return 0;
    if (is_a<GiNaC::add>(e)) {
        numeric d = 0;
        for (const ex& t : e) d = std::max(d, degreeOf(t));
        return d;
    }
    if (is_a<GiNaC::mul>(e)) {
        numeric d = 0;
        for (const ex& f : e) d += degreeOf(f);
        return d;
    }
    if (is_a<GiNaC::power>(e) && is_a<numeric>(e.op(1)) && ex_to<numeric>(e.op(1)).is_real())
        return degreeOf(e.op(0)) * ex_to<numeric>(e.op(1));
    return 1;
}

bool isUnit(const numeric& k) { return GiNaC::abs(k).is_equal(1); }

// How many numbers other than ±1 (exponents aside) show in e when a product's
// coefficient goes back into its one sum wherever fewer show then (as product() does).
std::size_t numbersShown(const ex& e) {
    if (is_a<numeric>(e)) return isUnit(ex_to<numeric>(e)) ? 0 : 1;
    if (is_a<GiNaC::power>(e)) return numbersShown(e.op(0));
    if (is_a<GiNaC::add>(e)) {
        std::size_t n = 0;
        for (const ex& t : e) n += numbersShown(t);
        return n;
    }
    if (!is_a<GiNaC::mul>(e)) return 0;
    numeric k = 1;
    std::size_t others = 0, sums = 0;
    ex sum;
    for (const ex& f : e) {
        if (is_a<numeric>(f)) {
            k = ex_to<numeric>(f);
        } else if (is_a<GiNaC::add>(f)) {
            sum = f;
            ++sums;
            others += numbersShown(f);
        } else {
            others += numbersShown(f);
        }
    }
    if (isUnit(k)) return others;
    if (sums != 1) return others + 1;
    GiNaC::exvector terms;
    for (const ex& t : sum) terms.push_back(t * k);
    return std::min(others + 1, others - numbersShown(sum) + numbersShown(GiNaC::add(terms)));
}

}  // namespace

struct DisplayBuilder::Symbol {
    SymbolMeaning meaning;
    DisplayPtr node;
    FactorKey key;
};

// A factor of a product: base^exp with exp > 0 (a denominator's factor is kept with its
// exponent's sign turned).
struct DisplayBuilder::Factor {
    ex base;
    numeric exp;
    bool negated = false;  // a sum shown with its signs turned, so its first term is positive
    const Symbol* symbol = nullptr;
    mutable std::optional<FactorKey> key = std::nullopt;  // not a symbol's: made when first compared
};

struct DisplayBuilder::Product {
    numeric coef = 1;
    std::vector<Factor> num, den;  // in display order
};

struct DisplayBuilder::Term {
    numeric coef;  // the term's coefficient; the node shows its magnitude
    DisplayPtr node;
    bool more = false;  // "⋯ (N more terms)" of a cut sum
};

DisplayBuilder::DisplayBuilder(DisplayOptions options) : options_(std::move(options)), numbers_(options_.typedDecimals, options_.allDigits) {}
DisplayBuilder::~DisplayBuilder() = default;

DisplayPtr DisplayBuilder::number(const numeric& n, bool standalone) const {
    return options_.readableNumbers ? numbers_.node(n, standalone) : numberNode(n);
}

bool DisplayBuilder::decimal(const numeric& n) const { return options_.readableNumbers && numbers_.decimal(n); }

DisplayPtr DisplayBuilder::operator()(const ex& e) {
    // A number standing alone (a DH entry 0.5) reads as typed.
    const auto entry = [this](const ex& x) { return is_a<numeric>(x) ? number(ex_to<numeric>(x), true) : node(x); };
    if (!is_a<GiNaC::matrix>(e)) return entry(e);
    const GiNaC::matrix& m = ex_to<GiNaC::matrix>(e);
    auto n = std::make_shared<DisplayNode>();
    n->kind = DisplayKind::Matrix;
    n->rows.assign(m.rows(), std::vector<DisplayPtr>(m.cols()));
    for (unsigned i = 0; i < m.rows(); ++i)
        for (unsigned j = 0; j < m.cols(); ++j) n->rows[i][j] = entry(m(i, j));
    return n;
}

DisplayBuilder::Symbol& DisplayBuilder::symbol(const GiNaC::symbol& s) {
    const std::string& name = s.get_name();
    std::unique_ptr<Symbol>& entry = symbols_[name];
    if (!entry) {
        entry = std::make_unique<Symbol>();
        entry->meaning = symbolMeaning(name, options_.names);
        entry->key = symbolFactorKey(name, entry->meaning);
        if (options_.givenSymbols)
            if (auto it = options_.givenSymbols->find(name); it != options_.givenSymbols->end()) entry->node = it->second;
        if (!entry->node) entry->node = symbolNode(name, entry->meaning, options_.names);
    }
    return *entry;
}

DisplayPtr DisplayBuilder::node(const ex& e) {
    if (is_a<GiNaC::add>(e)) return sum(e, false);
    if (is_a<numeric>(e)) return number(ex_to<numeric>(e));
    if (is_a<GiNaC::symbol>(e)) return symbol(ex_to<GiNaC::symbol>(e)).node;
    if (is_a<GiNaC::relational>(e)) {
        struct Op {
            unsigned flag;
            const char *plain, *text, *latex;
        };
        using GiNaC::info_flags;
        static const Op ops[] = {{info_flags::relation_equal, "==", "=", "="},
                                 {info_flags::relation_not_equal, "!=", "≠", "\\neq"},
                                 {info_flags::relation_less, "<", "<", "<"},
                                 {info_flags::relation_less_or_equal, "<=", "≤", "\\leq"},
                                 {info_flags::relation_greater, ">", ">", ">"},
                                 {info_flags::relation_greater_or_equal, ">=", "≥", "\\geq"}};
        const Op* op = &ops[0];
        for (const Op& o : ops)
            if (e.info(o.flag)) op = &o;
        auto n = std::make_shared<DisplayNode>();
        n->kind = DisplayKind::Equation;
        n->children = {node(e.lhs()), node(e.rhs())};
        n->plain = op->plain;
        n->text = std::string(" ") + op->text + " ";
        n->latex = std::string(" ") + op->latex + " ";
        return n;
    }
    if (is_a<GiNaC::lst>(e)) {
        std::vector<DisplayPtr> items;
        for (const ex& item : e) items.push_back(node(item));
        return displayNode(DisplayKind::List, std::move(items));
    }
    Product p = product(e);
    if (!p.coef.is_real() || !p.coef.is_negative()) return productNode(p.coef, p);
    return displayNegated(productNode(-p.coef, p));
}

// A factor's base that is not a symbol: a constant, a function, a sum, a power with a
// symbolic exponent, or another GiNaC class.
DisplayPtr DisplayBuilder::atom(const ex& e) {
    if (is_a<GiNaC::add>(e)) return sum(e, false);
    if (is_a<numeric>(e)) return number(ex_to<numeric>(e));
    if (is_a<GiNaC::constant>(e)) {
        auto n = std::make_shared<DisplayNode>();
        n->kind = DisplayKind::Symbol;
        n->name = n->plain = (std::ostringstream() << e).str();
        if (n->name == "Pi") {
            n->plain = "pi";  // as SymPy, Python's math and our scene files write it (GiNaC's name stays the sort key)
            n->text = "π";
            n->latex = "\\pi";
        } else if (n->name == "Euler") {
            n->text = "γ";
            n->latex = "\\gamma";
        } else {
            n->text = n->name;
            n->latex = "\\mathrm{" + n->name + "}";
            n->upright = true;
        }
        return n;
    }
    if (is_a<GiNaC::function>(e)) {
        static const std::map<std::string, std::string> known = {{"sin", "\\sin"},     {"cos", "\\cos"},    {"tan", "\\tan"},
                                                                 {"exp", "\\exp"},     {"log", "\\ln"},     {"sinh", "\\sinh"},
                                                                 {"cosh", "\\cosh"},   {"tanh", "\\tanh"},  {"asin", "\\arcsin"},
                                                                 {"acos", "\\arccos"}, {"atan", "\\arctan"}};
        auto n = std::make_shared<DisplayNode>();
        n->kind = DisplayKind::Function;
        n->text = n->plain = n->name = ex_to<GiNaC::function>(e).get_name();
        const auto it = known.find(n->name);
        n->latex = it != known.end() ? it->second : "\\operatorname{" + latexEscape(n->name) + "}";
        n->upright = true;
        for (const ex& a : e) n->children.push_back(node(a));
        return n;
    }
    if (is_a<GiNaC::power>(e)) return displayNode(DisplayKind::Power, {fenced(node(e.op(0)), atomPrecedence), node(e.op(1))});
    if (is_a<GiNaC::mul>(e) || is_a<GiNaC::symbol>(e) || is_a<GiNaC::relational>(e) || is_a<GiNaC::lst>(e)) return node(e);
    std::ostringstream plain, latex;  // other GiNaC classes: their own printer
    plain << e;
    latex << GiNaC::latex << e;
    return displayRaw("(" + plain.str() + ")", "(" + latex.str() + ")", "(" + plain.str() + ")");
}

// ---- sums

const std::vector<DisplayBuilder::Term>& DisplayBuilder::orderedTerms(const ex& e) {
    const GiNaC::basic* object = &ex_to<GiNaC::basic>(e);
    if (auto it = sums_.find(object); it != sums_.end()) return it->second.second;
    struct Keyed {
        TermKey key;
        Term term;
    };
    std::vector<Keyed> terms;
    for (const ex& t : e) {  // each term, its number last
        Product p = product(t);
        Keyed k;
        TermKey& key = k.key;
        for (const Factor& f : p.num) {
            if (f.symbol && f.exp.is_pos_integer()) {
                key.add(f.symbol->meaning, f.exp.to_int());
                key.degree += f.exp;
            } else {
                addToKey(f.base, key);
                key.degree += degreeOf(f.base) * f.exp;
            }
        }
        for (const Factor& f : p.den) {
            addToKey(f.base, key);
            key.degree -= degreeOf(f.base) * f.exp;
        }
        std::sort(key.velocities.begin(), key.velocities.end());
        key.text = keyText(*productNode(1, p));
        k.term.coef = p.coef;
        k.term.node = productNode(p.coef.is_real() && p.coef.is_negative() ? -p.coef : p.coef, p);
        terms.push_back(std::move(k));
    }
    std::stable_sort(terms.begin(), terms.end(), [](const Keyed& a, const Keyed& b) {
        if (const int c = compareTermKeys(a.key, b.key); c != 0) return c < 0;
        const auto value = [](const numeric& n) { return n.is_real() ? n.to_double() : 0.0; };
        return value(a.term.coef) < value(b.term.coef);
    });
    std::vector<Term> ordered;
    const bool cut = options_.cutLongSums && terms.size() > maxTypesetTerms;
    for (std::size_t i = 0; i < (cut ? keptTypesetTerms : terms.size()); ++i) ordered.push_back(std::move(terms[i].term));
    if (cut) ordered.push_back({0, displayMoreTerms(terms.size() - keptTypesetTerms), true});
    return sums_.try_emplace(object, e, std::move(ordered)).first->second.second;
}

DisplayPtr DisplayBuilder::sum(const ex& e, bool negate) {
    auto n = std::make_shared<DisplayNode>();
    n->kind = DisplayKind::Sum;
    for (const Term& t : orderedTerms(e)) {
        n->children.push_back(t.node);
        n->negative.push_back(!t.more && (t.coef.is_real() && t.coef.is_negative()) != negate);
    }
    return n;
}

// What the symbols and functions anywhere in e add to a term's key.
void DisplayBuilder::addToKey(const ex& e, TermKey& key) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
        if (is_a<GiNaC::symbol>(*it)) key.add(symbol(ex_to<GiNaC::symbol>(*it)).meaning, 0);
        if (is_a<GiNaC::function>(*it)) {
            const std::string name = ex_to<GiNaC::function>(*it).get_name();
            if (name == "sin" || name == "cos" || name == "tan") key.trig = true;
        }
    }
}

// ---- products

// e as a coefficient times factors in display order. GiNaC gives a sum factor with an
// integer power the sign that makes its leading term positive in GiNaC's hash order,
// which varies: (b−a)² or (a−b)². Here the leading term in *our* order is positive, an
// odd power's sign moved to the coefficient.
DisplayBuilder::Product DisplayBuilder::product(const ex& e) {
    Product p;
    const auto factor = [&](const ex& base, const numeric& k) {
        Factor f{base, k};
        if (is_a<GiNaC::add>(base) && k.is_integer() && orderedTerms(base).front().coef.is_negative()) {
            f.negated = true;
            if (k.is_odd()) p.coef = -p.coef;
        }
        if (is_a<GiNaC::symbol>(base)) f.symbol = &symbol(ex_to<GiNaC::symbol>(base));
        if (k.is_negative()) {
            f.exp = -k;
            p.den.push_back(std::move(f));
        } else {
            p.num.push_back(std::move(f));
        }
    };
    const auto one = [&](const ex& x) {
        if (is_a<numeric>(x)) p.coef *= ex_to<numeric>(x);
        else if (is_a<GiNaC::power>(x) && is_a<numeric>(x.op(1)) && ex_to<numeric>(x.op(1)).is_real())
            factor(x.op(0), ex_to<numeric>(x.op(1)));
        else factor(x, 1);
    };
    if (is_a<GiNaC::mul>(e))
        for (const ex& x : e) one(x);  // its factors, then its coefficient
    else one(e);
    // GiNaC keeps a sum's numeric content in front (q̇2 (2a + 4b) is 2 q̇2 (a + 2b)); a
    // coefficient that is not a formula's (a decimal, 5·10⁻¹⁰) goes back into the sum,
    // and so does a formula's when fewer numbers show then: the textbook's
    // m (l² + 2/5 r²), not 1/5 m (5 l² + 2 r²); ½ m (l² + r²) stays.
    const auto isSum = [](const Factor& f) { return is_a<GiNaC::add>(f.base) && f.exp.is_equal(1); };
    if (!p.coef.is_equal(1) && !p.coef.is_equal(-1) && std::count_if(p.num.begin(), p.num.end(), isSum) == 1) {
        const auto it = std::find_if(p.num.begin(), p.num.end(), isSum);
        GiNaC::exvector terms;
        const numeric sign = it->negated ? numeric(-1) : numeric(1);
        for (const ex& t : it->base) terms.push_back(t * p.coef * sign);
        const ex distributed = GiNaC::add(terms);
        if (!formulaFactor(p.coef) || decimal(p.coef) || numbersShown(distributed) < 1 + numbersShown(it->base)) {
            p.num.erase(it);
            p.coef = 1;
            if (is_a<GiNaC::add>(distributed)) factor(distributed, 1);
            else one(distributed);
        }
    }
    // Likewise a square's: GiNaC writes (1.2 − a1 + ℓc1)² as 1/25 (6 − 5 a1 + 5 ℓc1)²; the
    // coefficient's root goes back in when fewer numbers show then (¼ m (a + b)² stays).
    const auto isSquare = [](const Factor& f) { return is_a<GiNaC::add>(f.base) && f.exp.is_equal(2); };
    if (p.coef.is_rational() && p.coef.is_positive() && !p.coef.is_equal(1) &&
        std::count_if(p.num.begin(), p.num.end(), isSquare) == 1 && GiNaC::sqrt(p.coef).is_rational()) {
        const auto it = std::find_if(p.num.begin(), p.num.end(), isSquare);
        const numeric root = GiNaC::sqrt(p.coef);
        GiNaC::exvector terms;
        for (const ex& t : it->base) terms.push_back(t * root);
        const ex distributed = GiNaC::add(terms);
        if (numbersShown(distributed) < 1 + numbersShown(it->base)) {
            p.num.erase(it);
            p.coef = 1;
            factor(distributed, 2);
        }
    }
    const auto byKey = [this](const Factor& a, const Factor& b) { return factorKey(a) < factorKey(b); };
    std::stable_sort(p.num.begin(), p.num.end(), byKey);
    std::stable_sort(p.den.begin(), p.den.end(), byKey);
    return p;
}

FactorKey DisplayBuilder::factorKey(const Factor& f) {
    if (f.symbol) return f.symbol->key;
    if (!f.key) {
        const int rank = is_a<numeric>(f.base) || is_a<GiNaC::constant>(f.base) ? numberRank
                         : is_a<GiNaC::function>(f.base)                        ? functionRank
                                                                                : sumRank;
        const DisplayPtr spelled = is_a<GiNaC::add>(f.base) ? sum(f.base, f.negated) : atom(f.base);
        f.key = FactorKey{rank, {}, keyText(*spelled)};
    }
    return *f.key;
}

DisplayPtr DisplayBuilder::factorNode(const Factor& f) {
    const DisplayPtr base = f.negated ? sum(f.base, true) : f.symbol ? f.symbol->node : atom(f.base);
    if (isOne(f.exp)) return fenced(base, productPrecedence + 1);
    if (f.exp == numeric(1, 2)) return displayNode(DisplayKind::Root, {base});
    const bool function = is_a<GiNaC::function>(f.base);
    return displayNode(DisplayKind::Power, {function ? base : fenced(base, atomPrecedence), exponentNode(f.exp)});
}

// c times the product of p's factors (c ≥ 0: the sign is the caller's): 2, ½, 0.5 in
// front; a fraction's denominator joins the factors below the line.
DisplayPtr DisplayBuilder::productNode(const numeric& c, const Product& p) {
    std::vector<DisplayPtr> num, den;
    if (p.den.empty() || !c.is_rational() || decimal(c)) {
        if (!isOne(c)) num.push_back(number(c));
    } else {
        if (c.numer() != 1) num.push_back(numberNode(c.numer()));
        if (c.denom() != 1) den.push_back(numberNode(c.denom()));
    }
    for (const Factor& f : p.num) num.push_back(factorNode(f));
    for (const Factor& f : p.den) den.push_back(factorNode(f));
    if (den.empty()) return productOf(std::move(num));
    return displayNode(DisplayKind::Fraction, {productOf(std::move(num)), productOf(std::move(den))});
}

DisplayPtr buildDisplay(const ex& e, const DisplayOptions& options) { return DisplayBuilder(options)(e); }

}  // namespace ll::present
