#include "core/symbolic/derivation_evaluator.hpp"

#include <stdexcept>

#include "core/model/argument_checks.hpp"

namespace ll::symbolic {

DerivationEvaluator::DerivationEvaluator(const Derivation& derivation) : d_(derivation) {}

GiNaC::lst DerivationEvaluator::state(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, double t) const {
    const auto n = static_cast<Eigen::Index>(d_.q.size());
    requireSize("DerivationEvaluator::value", "q", q.size(), n, "the system", "coordinates");
    requireSize("DerivationEvaluator::value", "qd", qd.size(), n, "the system", "coordinates");
    GiNaC::lst l;
    for (size_t i = 0; i < d_.q.size(); ++i) {
        l.append(d_.q[i] == q[i]);
        l.append(d_.qd[i] == qd[i]);
    }
    l.append(d_.t == t);
    return l;
}

double DerivationEvaluator::value(const GiNaC::ex& e, const Eigen::VectorXd& q, const Eigen::VectorXd& qd, double t) const {
    const GiNaC::ex v = e.subs(d_.trigToFunctions).subs(d_.parameterValues).subs(state(q, qd, t)).evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real())
        throw std::runtime_error("expression does not evaluate to a real number");
    return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
}

Eigen::MatrixXd DerivationEvaluator::value(const GiNaC::matrix& m, const Eigen::VectorXd& q, const Eigen::VectorXd& qd, double t) const {
    Eigen::MatrixXd out(m.rows(), m.cols());
    for (unsigned r = 0; r < m.rows(); ++r)
        for (unsigned c = 0; c < m.cols(); ++c) out(r, c) = value(m(r, c), q, qd, t);
    return out;
}

}  // namespace ll::symbolic
