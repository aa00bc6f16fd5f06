#include "core/present/textbook_form.hpp"

#include <algorithm>
#include <map>

#include "core/present/number_spelling.hpp"
#include "core/symbolic/trig_context.hpp"

namespace ll::present {
namespace {

using GiNaC::ex, GiNaC::ex_to, GiNaC::is_a, GiNaC::numeric;

// Entries with more terms than this are shown as derived (expanded, in display order),
// without the c_i² → s_i² choice, angle sums, common factors and grouping, whose cost
// grows faster than the entry and which no reader follows at that length anyway.
constexpr std::size_t maxShapedTerms = 300;

std::size_t termCount(const ex& e) { return is_a<GiNaC::add>(e) ? e.nops() : 1; }

// How long e reads: its symbols, functions and numbers other than ±1, each counted
// where it occurs.
std::size_t size(const ex& e) {
    std::size_t n = 0;
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (is_a<GiNaC::symbol>(*it) || is_a<GiNaC::function>(*it) || is_a<GiNaC::constant>(*it) ||
            (is_a<numeric>(*it) && !GiNaC::abs(ex_to<numeric>(*it)).is_equal(1)))
            ++n;
    return n;
}

// m, m1, m_cart: a mass, by the naming rules of derivation.hpp.
bool isMassName(const std::string& name, std::string& digits) {
    digits = name.substr(std::min<std::size_t>(1, name.size()));
    const bool numbered =
        !digits.empty() && digits.size() < 9 && std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!numbered) digits.clear();
    return name == "m" || (name[0] == 'm' && (name[1] == '_' || numbered));
}

// The common factor of the terms of an expanded sum, velocities left inside (the
// textbook's −m2 a1 ℓc2 s2 (q̇1 + q̇2), not … q̇2 (…)): the symbols every term has, at
// their least power, with the rational content and a common sign. 1 when none.
GiNaC::ex commonFactor(const GiNaC::ex& e, const std::vector<GiNaC::symbol>& velocities) {
    if (!GiNaC::is_a<GiNaC::add>(e)) return 1;
    std::map<GiNaC::ex, int, GiNaC::ex_is_less> common;
    bool first = true, allNegative = true, rational = true;
    GiNaC::numeric gcdNum = 0, lcmDen = 1;
    for (const GiNaC::ex& term : e) {
        std::map<GiNaC::ex, int, GiNaC::ex_is_less> here;
        GiNaC::numeric coef = 1;
        for (const GiNaC::ex& f : GiNaC::is_a<GiNaC::mul>(term) ? term : GiNaC::ex(GiNaC::lst{term})) {
            if (GiNaC::is_a<GiNaC::numeric>(f)) {
                coef = GiNaC::ex_to<GiNaC::numeric>(f);
            } else if (GiNaC::is_a<GiNaC::symbol>(f)) {
                here[f] = 1;
            } else if (GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::symbol>(f.op(0)) && f.op(1).info(GiNaC::info_flags::posint)) {
                here[f.op(0)] = GiNaC::ex_to<GiNaC::numeric>(f.op(1)).to_int();
            }
        }
        if (!coef.is_rational()) rational = false;
        if (rational) {
            gcdNum = GiNaC::gcd(gcdNum, coef.numer());
            lcmDen = GiNaC::lcm(lcmDen, coef.denom());
        }
        allNegative = allNegative && coef.is_real() && coef.is_negative();
        if (first) {
            common = here;
            first = false;
        } else {
            for (auto it = common.begin(); it != common.end();) {
                const auto h = here.find(it->first);
                if (h == here.end()) {
                    it = common.erase(it);
                } else {
                    it->second = std::min(it->second, h->second);
                    ++it;
                }
            }
        }
        if (common.empty()) return 1;
    }
    GiNaC::ex factor = 1;
    for (const auto& entry : common) {  // not a structured binding: clang 14 (fuzz build) cannot capture one
        const auto& symbol = entry.first;
        if (std::none_of(velocities.begin(), velocities.end(), [&](const GiNaC::symbol& v) { return symbol.is_equal(v); }))
            factor *= GiNaC::pow(symbol, entry.second);
    }
    if (factor.is_equal(1)) return 1;
    GiNaC::numeric content = rational && formulaFactor(gcdNum / lcmDen) ? gcdNum / lcmDen : GiNaC::numeric(1);
    if (allNegative) content = -content;
    return content * factor;
}

// sum as the square of a linear form when it is one and that reads shorter: the 2R's
// 1.44 − 2.4 a1 + 2.4 ℓc1 − 2 a1 ℓc1 + a1² + ℓc1² is (1.2 − a1 + ℓc1)². Only sums of
// symbols of degree at most two with rational coefficients are tried; the form is found
// from the first symbol's square, its products and its linear term, then checked by
// expanding. The square's factor goes inside when it is a rational square, else in front
// when it reads as a formula's (2 (…)²); the signs inside are the fewer negative ones.
// Returns sum itself otherwise.
GiNaC::ex squareForm(const GiNaC::ex& sum) {
    if (!is_a<GiNaC::add>(sum) || sum.nops() < 3) return sum;
    std::vector<ex> symbols;
    for (const ex& term : sum) {
        for (const ex& f : is_a<GiNaC::mul>(term) ? term : GiNaC::ex(GiNaC::lst{term})) {
            ex base = f;
            if (is_a<GiNaC::power>(f)) {
                if (!f.op(1).is_equal(2)) return sum;
                base = f.op(0);
            }
            if (is_a<numeric>(base)) {
                if (!ex_to<numeric>(base).is_rational()) return sum;
                continue;
            }
            if (!is_a<GiNaC::symbol>(base)) return sum;
            if (std::none_of(symbols.begin(), symbols.end(), [&](const ex& s) { return s.is_equal(base); })) symbols.push_back(base);
        }
    }
    if (symbols.empty()) return sum;
    std::sort(symbols.begin(), symbols.end(), GiNaC::ex_is_less());
    const ex& x1 = symbols[0];
    const ex a1 = sum.coeff(x1, 2);
    if (!is_a<numeric>(a1) || a1.is_zero()) return sum;
    const numeric c = ex_to<numeric>(a1);  // sum = c (x1 + k0 + Σ k_i x_i)²
    ex form = x1 + sum.coeff(x1, 1).subs([&] {
        GiNaC::exmap zero;
        for (std::size_t i = 1; i < symbols.size(); ++i) zero[symbols[i]] = 0;
        return zero;
    }()) / (2 * c);
    for (std::size_t i = 1; i < symbols.size(); ++i) {
        const ex k = sum.coeff(x1, 1).coeff(symbols[i], 1) / (2 * c);
        if (!is_a<numeric>(k)) return sum;
        form += k * symbols[i];
    }
    if (!(c * GiNaC::pow(form, 2) - sum).expand().is_zero()) return sum;
    // The fewer negative coefficients inside.
    std::size_t negative = 0, terms = 0;
    for (const ex& term : form) {
        ++terms;
        const ex k = is_a<numeric>(term) ? term : is_a<GiNaC::mul>(term) && is_a<numeric>(term.op(term.nops() - 1)) ? term.op(term.nops() - 1) : ex(1);
        if (ex_to<numeric>(k).is_negative()) ++negative;
    }
    if (2 * negative > terms) form = (-form).expand();
    const numeric root = GiNaC::sqrt(GiNaC::abs(c));
    ex result;
    // GiNaC takes the integer content out again ((6/5 − a1 + ℓc1)² is 1/25 (6 − 5 a1 + 5 ℓc1)²);
    // the display builder puts it back in where fewer numbers show.
    if (root.is_rational()) result = (c.is_negative() ? ex(-1) : ex(1)) * GiNaC::pow((root * form).expand(), 2);
    else if (formulaFactor(c)) result = c * GiNaC::pow(form, 2);
    else return sum;
    return size(result) < size(sum) ? result : sum;
}

}  // namespace

TextbookForm::TextbookForm(const symbolic::Derivation& d) : d_(d), robot_(d.system == symbolic::SystemKind::Robot), combiner_(d.q) {}

Grouping TextbookForm::plainGrouping() const { return robot_ ? Grouping::Masses : Grouping::Parameters; }

ex TextbookForm::operator()(const ex& value, Grouping grouping) {
    if (is_a<GiNaC::matrix>(value)) {
        GiNaC::matrix m = ex_to<GiNaC::matrix>(value);
        for (unsigned r = 0; r < m.rows(); ++r)
            for (unsigned c = 0; c < m.cols(); ++c) m(r, c) = (*this)(m(r, c), grouping);
        return m;
    }
    auto& shaped = shaped_[static_cast<int>(grouping)];
    if (auto it = shaped.find(value); it != shaped.end()) return it->second;
    // Shaping (sines for cosines, angle sums) costs more than linear time and only
    // pays off on entries a reader can follow: larger ones stay as derived.
    ex e = value.expand();
    if (termCount(e) > maxShapedTerms) return shaped.emplace(value, e).first->second;
    e = robot_ ? combiner_.combine(shorterInSines(e)) : shorterInSines(e);
    // Robots pull a common factor out (m2 a1 ℓc2 s2 (…)); a typed Lagrangian keeps its
    // parameters inside, so the notes' spring term reads K2 (θ1 − θ2).
    const ex common = robot_ ? commonFactor(e, d_.qd) : ex(1);
    if (!common.is_equal(1)) e = (e / common).expand();
    const std::vector<GiNaC::symbol> groupBy = grouping == Grouping::Velocities ? d_.qd
                                               : grouping == Grouping::Masses   ? massSymbols(e)
                                                                                : parameters();
    e = common * collectForDisplay(e, groupBy);
    // A typed Lagrangian's expression reads as typed (½ K2 (θ1 − θ2)²) unless its shaped
    // form is shorter; its expansion shows where a step makes it (∂L/∂θ1).
    if (!robot_ && size(value) <= size(e)) e = value;
    return shaped.emplace(value, e).first->second;
}

std::vector<ex> TextbookForm::equationParts(int i) {
    std::vector<ex> parts;
    const std::size_t n = d_.q.size();
    for (std::size_t j = 0; j < n; ++j) parts.push_back((*this)(d_.B(i, j), plainGrouping()) * d_.qdd[j]);
    ex velocity = 0;
    std::size_t terms = 0;  // counted on the entries: expanding a long row first costs more than all the rest
    for (std::size_t j = 0; j < n; ++j) {
        velocity += d_.C(i, j) * d_.qd[j];
        terms += termCount(d_.C(i, j));
    }
    if (terms <= maxShapedTerms) {
        parts.push_back((*this)(velocity, Grouping::Velocities));
    } else {  // too long to factor: entry by entry, each shaped as C's
        for (std::size_t j = 0; j < n; ++j) parts.push_back((*this)(d_.C(i, j), Grouping::Velocities) * d_.qd[j]);
    }
    parts.push_back((*this)(d_.g(i, 0), plainGrouping()));
    return parts;
}

// The derivation keeps powers of c_i and reduces s_i² = 1 − c_i² (a canonical form); a
// textbook writes I1 s1², not I1 − I1 c1². For display, eliminate c_i² instead wherever
// that gives fewer terms.
ex TextbookForm::shorterInSines(const ex& value) const {
    using namespace GiNaC;  // is_ex_the_function is a macro naming GiNaC's function classes
    ex e = value.expand();
    const GiNaC::lst& trig = d_.trigToFunctions;  // c_i == cos(q_i), s_i == sin(q_i), in pairs
    for (std::size_t k = 0; k + 1 < trig.nops(); k += 2) {
        const ex c = trig.op(k).lhs(), s = trig.op(k + 1).lhs();
        if (!is_ex_the_function(trig.op(k).rhs(), cos) || e.degree(c) < 2) continue;
        const ex alternative = symbolic::reducePythagorean(e, c, s);
        if (termCount(alternative) < termCount(e)) e = alternative;
    }
    if (robot_) return e;
    // A typed Lagrangian's cos(θ), sin(θ) are functions of its coordinates: the derivation
    // wrote sin²θ as 1 − cos²θ; the user's sin²θ comes back where it is shorter.
    for (const GiNaC::symbol& q : d_.q) {
        const ex c = GiNaC::cos(q), s = GiNaC::sin(q);
        if (e.degree(c) < 2) continue;
        const ex alternative = symbolic::reducePythagorean(e, c, s);
        if (termCount(alternative) < termCount(e)) e = alternative;
    }
    return e;
}

std::vector<GiNaC::symbol> TextbookForm::parameters() const {
    std::vector<GiNaC::symbol> symbols;
    for (const ex& rel : d_.parameterValues)
        if (is_a<GiNaC::symbol>(rel.lhs())) symbols.push_back(ex_to<GiNaC::symbol>(rel.lhs()));
    return symbols;
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
        if (std::all_of(key.begin(), key.end(), [](int k) { return k == 0; })) single += term;
        else groups[key].push_back(cofactor);
    };
    if (is_a<GiNaC::add>(x))
        for (const ex& t : x) addTerm(t);
    else addTerm(x);
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
        numeric content = rational && formulaFactor(gcdNum / lcmDen) ? gcdNum / lcmDen : numeric(1);
        if (allNegative && rational) content = -content;
        ex sum = 0;
        for (const ex& c : cofactors) sum += c / content;
        result += content * monomial * squareForm(sum);
    }
    return result;
}

std::vector<GiNaC::symbol> massSymbols(const ex& e) {
    std::map<std::pair<long, std::string>, GiNaC::symbol> found;
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
        if (!is_a<GiNaC::symbol>(*it)) continue;
        const std::string& name = ex_to<GiNaC::symbol>(*it).get_name();
        std::string digits;
        if (!name.empty() && isMassName(name, digits))
            found.emplace(std::pair{digits.empty() ? -1L : std::stol(digits), name}, ex_to<GiNaC::symbol>(*it));
    }
    std::vector<GiNaC::symbol> out;
    for (auto& [key, s] : found) out.push_back(s);
    return out;
}

}  // namespace ll::present
