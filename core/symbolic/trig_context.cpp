#include "core/symbolic/trig_context.hpp"

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
}

GiNaC::ex TrigContext::reduce(const GiNaC::ex& e) const {
    GiNaC::ex r = e.expand();
    for (int i = 0; i < size(); ++i)
        if (revolute_[i]) r = reducePythagorean(r, s_[i], c_[i]);
    for (const auto& [s, c] : constantAngles_) r = reducePythagorean(r, s, c);
    return r;
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
