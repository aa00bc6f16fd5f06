#include "core/dynamics/finite_terms.hpp"

#include <cmath>

namespace ll {
namespace {

std::string vectorText(const Eigen::VectorXd& v) {
    std::string text = "[";
    for (Eigen::Index i = 0; i < v.size(); ++i) text += (i ? ", " : "") + formatValue(v[i]);
    return text + "]";
}

// "inf in B[1][2]" (1-based) for the first non-finite entry, or nothing.
std::optional<Message> firstNonFinite(const Eigen::MatrixXd& m, const char* name, bool vector) {
    using enum MessageId;
    for (Eigen::Index r = 0; r < m.rows(); ++r)
        for (Eigen::Index c = 0; c < m.cols(); ++c)
            if (!std::isfinite(m(r, c)))
                return vector ? message(NonFiniteVectorEntry, m(r, c), name, r + 1)
                              : message(NonFiniteMatrixEntry, m(r, c), name, r + 1, c + 1);
    return std::nullopt;
}

}  // namespace

std::optional<Diagnostic> nonFiniteTerm(const ModelTerms& terms, const Eigen::VectorXd& qdd, const Eigen::VectorXd& q,
                                        const Eigen::VectorXd& qd, const Message& where) {
    using enum MessageId;
    const struct {
        const char* name;
        MessageId notFinite;  // "the mass matrix is not finite ({1}) {2}"
        Eigen::MatrixXd value;
        bool vector;
    } quantities[] = {
        {"B", MassMatrixNotFinite, terms.B, false},
        {"C", CoriolisMatrixNotFinite, terms.C, false},
        {"g", GravityTorquesNotFinite, terms.g, true},
        {"Q", GeneralizedForcesNotFinite, terms.Q, true},
        {"Ekin", KineticEnergyNotFinite, Eigen::MatrixXd::Constant(1, 1, terms.Ekin), true},
        {"Epot", PotentialEnergyNotFinite, Eigen::MatrixXd::Constant(1, 1, terms.Epot), true},
        {"qdd", AccelerationNotFinite, qdd, true},
    };
    for (const auto& quantity : quantities) {
        std::optional<Message> bad = firstNonFinite(quantity.value, quantity.name, quantity.vector);
        if (!bad) continue;
        if (quantity.value.size() == 1 && quantity.vector) bad = literal(formatValue(quantity.value(0, 0)));
        return Diagnostic{Severity::Error, quantity.name, message(TooLargeForDoublePrecision, message(quantity.notFinite, *bad, where)),
                          message(NonFiniteTermHint, vectorText(q), vectorText(qd))};
    }
    return std::nullopt;
}

}  // namespace ll
