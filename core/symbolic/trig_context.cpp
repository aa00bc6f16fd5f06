#include "core/symbolic/trig_context.hpp"

namespace ll::symbolic {

TrigContext::TrigContext(std::vector<bool> revolute) : revolute_(std::move(revolute)), t_("t") {
    for (int i = 1; i <= size(); ++i) {
        const std::string k = std::to_string(i);
        q_.emplace_back("q" + k);
        qd_.emplace_back("qd" + k);
        c_.emplace_back("c" + k);
        s_.emplace_back("s" + k);
    }
}

GiNaC::ex TrigContext::reduce(const GiNaC::ex& e) const {
    GiNaC::ex r = e.expand();
    for (int i = 0; i < size(); ++i) {
        if (!revolute_[i] || r.degree(s_[i]) < 2) continue;
        // rem with respect to s_i: the remainder of degree < 2 in s_i (platform notes:
        // the fastest way GiNaC offers).
        r = GiNaC::rem(r, GiNaC::pow(s_[i], 2) + GiNaC::pow(c_[i], 2) - 1, s_[i]).expand();
    }
    return r;
}

GiNaC::matrix TrigContext::reduce(const GiNaC::matrix& m) const {
    GiNaC::matrix r(m.rows(), m.cols());
    for (unsigned i = 0; i < m.rows(); ++i)
        for (unsigned j = 0; j < m.cols(); ++j) r(i, j) = reduce(m(i, j));
    return r;
}

GiNaC::ex TrigContext::diffq(const GiNaC::ex& e, int k) const {
    GiNaC::ex d = e.diff(q_[k]);
    if (revolute_[k]) d += c_[k] * e.diff(s_[k]) - s_[k] * e.diff(c_[k]);
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
