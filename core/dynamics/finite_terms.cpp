#include "core/dynamics/finite_terms.hpp"

#include <cmath>

namespace ll {
namespace {

std::string vectorText(const Eigen::VectorXd& v) {
    std::string text = "[";
    for (Eigen::Index i = 0; i < v.size(); ++i) text += (i ? ", " : "") + formatValue(v[i]);
    return text + "]";
}

// "inf in B[1][2]" (1-based) for the first non-finite entry, or "".
std::string firstNonFinite(const Eigen::MatrixXd& m, const std::string& name, bool vector) {
    for (Eigen::Index r = 0; r < m.rows(); ++r)
        for (Eigen::Index c = 0; c < m.cols(); ++c)
            if (!std::isfinite(m(r, c)))
                return formatValue(m(r, c)) + " in " + name + "[" + std::to_string(r + 1) + "]" +
                       (vector ? "" : "[" + std::to_string(c + 1) + "]");
    return "";
}

}  // namespace

std::optional<Diagnostic> nonFiniteTerm(const ModelTerms& terms, const Eigen::VectorXd& qdd, const Eigen::VectorXd& q,
                                        const Eigen::VectorXd& qd, const std::string& where) {
    const struct {
        const char* name;
        const char* meaning;
        Eigen::MatrixXd value;
        bool vector;
    } quantities[] = {
        {"B", "the mass matrix", terms.B, false},
        {"C", "the Coriolis/centrifugal matrix", terms.C, false},
        {"g", "the gravity and spring torques g = dEpot/dq", terms.g, true},
        {"Q", "the generalized forces", terms.Q, true},
        {"Ekin", "the kinetic energy", Eigen::MatrixXd::Constant(1, 1, terms.Ekin), true},
        {"Epot", "the potential energy", Eigen::MatrixXd::Constant(1, 1, terms.Epot), true},
        {"qdd", "the acceleration", qdd, true},
    };
    for (const auto& quantity : quantities) {
        std::string bad = firstNonFinite(quantity.value, quantity.name, quantity.vector);
        if (bad.empty()) continue;
        if (quantity.value.size() == 1 && quantity.vector) bad = formatValue(quantity.value(0, 0));
        return Diagnostic{Severity::Error, quantity.name,
                          std::string(quantity.meaning) + " is not finite (" + bad + ") " + where +
                              ": a number in the scene is too large for double precision here",
                          "at q = " + vectorText(q) + ", qd = " + vectorText(qd) +
                              ", a value passed about 1.8e308; check the exponents of the largest values"};
    }
    return std::nullopt;
}

}  // namespace ll
