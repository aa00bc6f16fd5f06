#include "core/symbolic/trig_context.hpp"

#include <algorithm>
#include <cmath>

namespace ll::symbolic {

TrigContext::TrigContext(std::vector<bool> revolute) : revolute_(std::move(revolute)), t_(sharedSymbol("t")) {
    for (int i = 1; i <= size(); ++i) {
        const std::string k = std::to_string(i);
        q_.push_back(sharedSymbol("q" + k));
        qd_.push_back(sharedSymbol("qd" + k));
        c_.push_back(sharedSymbol("c" + k));
        s_.push_back(sharedSymbol("s" + k));
    }
}

std::vector<GiNaC::symbol> TrigContext::symbols(const std::vector<GiNaC::ex>& shared) {
    std::vector<GiNaC::symbol> out;
    out.reserve(shared.size());
    for (const GiNaC::ex& s : shared) out.push_back(symbolOf(s));
    return out;
}

GiNaC::ex reducePythagorean(const GiNaC::ex& e, const GiNaC::ex& x, const GiNaC::ex& y) {
    const int degree = e.degree(x);
    if (degree < 2) return e;
    if (e.info(GiNaC::info_flags::rational_polynomial))  // the fastest way GiNaC offers (platform notes)
        return GiNaC::rem(e, GiNaC::pow(x, 2) + GiNaC::pow(y, 2) - 1, x, false).expand();
    const GiNaC::ex oneMinus = 1 - GiNaC::pow(y, 2);
    GiNaC::ex r = 0;
    for (int k = 0; k <= degree; ++k) {
        const GiNaC::ex coefficient = e.coeff(x, k);
        if (!coefficient.is_zero()) r += coefficient * GiNaC::pow(x, k % 2) * GiNaC::pow(oneMinus, k / 2);
    }
    return r.expand();
}

void TrigContext::addConstantAngle(const GiNaC::ex& angle) {
    using namespace GiNaC;  // is_ex_the_function is a macro naming GiNaC's function classes
    const ex s = GiNaC::sin(angle), c = GiNaC::cos(angle);
    // GiNaC evaluated it (π/3 → √3/2, a float): no function left to reduce.
    if (!is_ex_the_function(s, sin) || !is_ex_the_function(c, cos)) return;
    for (const auto& [known, unused] : constantAngles_)
        if (known.is_equal(s)) return;
    constantAngles_.emplace_back(s, c);
    if (is_a<numeric>(angle.evalf())) {
        folded_[s] = s.evalf();
        folded_[c] = c.evalf();
    }
}

GiNaC::ex TrigContext::reduce(const GiNaC::ex& e) const {
    if (!folded_.empty()) return reduceFolded(e);
    GiNaC::ex r = e.expand();
    for (int i = 0; i < size(); ++i)
        if (revolute_[i]) r = reducePythagorean(r, s_[i], c_[i]);
    for (const auto& [s, c] : constantAngles_) r = reducePythagorean(r, s, c);
    return r;
}

namespace {

// The numeric factor of a term of an expanded sum.
GiNaC::numeric coefficientOf(const GiNaC::ex& term) {
    if (GiNaC::is_a<GiNaC::numeric>(term)) return GiNaC::ex_to<GiNaC::numeric>(term);
    GiNaC::numeric c = 1;
    if (GiNaC::is_a<GiNaC::mul>(term))
        for (const GiNaC::ex& factor : term)
            if (GiNaC::is_a<GiNaC::numeric>(factor)) c *= GiNaC::ex_to<GiNaC::numeric>(factor);
    return c;
}

// One term with every power s^k (k ≥ 2) of the pairs' sines written s^(k mod 2) (1 − c²)^(k div 2),
// or the term itself (changed false).
GiNaC::ex lowerSines(const GiNaC::ex& term, const std::vector<std::pair<GiNaC::ex, GiNaC::ex>>& pairs, bool& changed) {
    const auto lower = [&](const GiNaC::ex& factor) -> GiNaC::ex {
        if (!GiNaC::is_a<GiNaC::power>(factor) || !GiNaC::is_a<GiNaC::numeric>(factor.op(1))) return factor;
        const GiNaC::numeric& k = GiNaC::ex_to<GiNaC::numeric>(factor.op(1));
        if (!k.is_pos_integer() || k.to_int() < 2) return factor;
        for (const auto& [s, c] : pairs)
            if (factor.op(0).is_equal(s)) {
                changed = true;
                return GiNaC::pow(s, k.to_int() % 2) * GiNaC::pow(1 - GiNaC::pow(c, 2), k.to_int() / 2);
            }
        return factor;
    };
    if (!GiNaC::is_a<GiNaC::mul>(term)) return lower(term);
    GiNaC::exvector factors;
    for (const GiNaC::ex& f : term) factors.push_back(lower(f));
    return changed ? GiNaC::ex(GiNaC::mul(factors)) : term;
}

}  // namespace

GiNaC::ex TrigContext::reduceFolded(const GiNaC::ex& e) const {
    GiNaC::ex r = e.subs(folded_, GiNaC::subs_options::no_pattern).expand();
    // s_i² → 1 − c_i² term by term, all sines in one pass: only the terms that change are
    // expanded again (their (1 − c²)ᵏ brings no sine back).
    std::vector<std::pair<GiNaC::ex, GiNaC::ex>> pairs;
    for (int i = 0; i < size(); ++i)
        if (revolute_[i]) pairs.emplace_back(s_[i], c_[i]);
    for (const auto& [s, c] : constantAngles_)
        if (!folded_.count(s)) pairs.emplace_back(s, c);
    GiNaC::exvector kept, lowered;
    for (const GiNaC::ex& term : GiNaC::is_a<GiNaC::add>(r) ? r : GiNaC::ex(GiNaC::lst{r})) {
        bool changed = false;
        const GiNaC::ex t = lowerSines(term, pairs, changed);
        (changed ? lowered : kept).push_back(changed ? t : term);
    }
    r = GiNaC::ex(GiNaC::add(kept)) + GiNaC::ex(GiNaC::add(lowered)).expand();
    if (!GiNaC::is_a<GiNaC::add>(r)) return r;
    double largest = 0;
    for (const GiNaC::ex& term : r) largest = std::max(largest, std::abs(coefficientOf(term).to_double()));
    GiNaC::exvector significant;
    for (const GiNaC::ex& term : r) {
        const GiNaC::numeric c = coefficientOf(term);
        if (c.is_rational() || std::abs(c.to_double()) >= 1e-12 * largest) significant.push_back(term);
    }
    return GiNaC::add(significant);
}

GiNaC::matrix TrigContext::reduce(const GiNaC::matrix& m) const {
    GiNaC::matrix r(m.rows(), m.cols());
    for (unsigned i = 0; i < m.rows(); ++i)
        for (unsigned j = 0; j < m.cols(); ++j) r(i, j) = reduce(m(i, j));
    return r;
}

GiNaC::ex TrigContext::diffq(const GiNaC::ex& e, int k) const {
    GiNaC::ex d = e.diff(q(k));
    if (revolute_[k]) d += c_[k] * e.diff(s(k)) - s_[k] * e.diff(c(k));
    return d;
}

GiNaC::matrix TrigContext::diffq(const GiNaC::matrix& m, int k) const {
    GiNaC::matrix r(m.rows(), m.cols());
    for (unsigned i = 0; i < m.rows(); ++i)
        for (unsigned j = 0; j < m.cols(); ++j) r(i, j) = diffq(m(i, j), k);
    return r;
}

GiNaC::lst TrigContext::toFunctions() const {
    GiNaC::lst l;
    for (int i = 0; i < size(); ++i)
        if (revolute_[i]) {
            l.append(c_[i] == GiNaC::cos(q_[i]));
            l.append(s_[i] == GiNaC::sin(q_[i]));
        }
    return l;
}

}  // namespace ll::symbolic
