#include "core/symbolic/lagrangian_derivation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <tuple>
#include <sstream>

#include <Eigen/Eigenvalues>

#include "core/dynamics/christoffel.hpp"
#include "core/symbolic/expression.hpp"
#include "core/symbolic/lagrangian_fields.hpp"
#include "core/model/actuation.hpp"
#include "core/model/diagnostics.hpp"
#include "core/symbolic/exact_numbers.hpp"
#include "core/symbolic/ginac_lock.hpp"

namespace ll::symbolic {
namespace {

using GiNaC::ex;
using GiNaC::matrix;

std::string str(const ex& e) {
    std::ostringstream out;
    out << e;
    return out.str();
}

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", std::abs(v) < 1e-14 ? 0.0 : v);
    return text;
}

bool isZero(const ex& e) { return e.expand().normal().is_zero(); }

// sin(u)^n → sin(u)^(n mod 2) (1 − cos(u)²)^(n div 2) everywhere, expanded: B and C
// of hand-typed kinetic energies lose their sin² + cos² (a cart-pole's m (sin² + cos²)).
struct ReduceSinSquares : GiNaC::map_function {
    ex operator()(const ex& e) override {
        if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_the_function<GiNaC::sin_SERIAL>(e.op(0)) && e.op(1).info(GiNaC::info_flags::posint)) {
            const long n = GiNaC::ex_to<GiNaC::numeric>(e.op(1)).to_long();
            if (n >= 2) {
                const ex u = e.op(0).op(0);
                return GiNaC::pow(GiNaC::sin(u), n % 2) * GiNaC::pow(1 - GiNaC::pow(GiNaC::cos(u), 2), n / 2);
            }
        }
        return e.map(*this);
    }
};

ex simplified(const ex& e) {
    ReduceSinSquares reduce;
    return reduce(e.expand()).expand();
}

// Parameter symbol == its exact value: numbers become the rationals they print as,
// parameters defined by expressions keep them exact (l1/3 stays a third).
GiNaC::exmap exactValues(const ParameterTable& table) {
    GiNaC::exmap values;
    for (const std::string& name : table.names()) {
        const ex& definition = table.definition(name);
        ex value;
        if (GiNaC::is_a<GiNaC::numeric>(definition))
            value = GiNaC::ex_to<GiNaC::numeric>(definition).is_rational() ? definition : exactNumber(table.value(name));
        else value = definition.subs(values);
        values[table.symbol(name)] = value;
    }
    return values;
}

GiNaC::lst toList(const GiNaC::exmap& map) {
    GiNaC::lst l;
    for (const auto& [from, to] : map) l.append(from == to);
    return l;
}

class LagrangianDeriver {
public:
    LagrangianDeriver(const Scene& scene, ParameterMode mode)
        : scene_(scene),
          spec_(*scene.lagrangian),
          n_(spec_.dof()),
          numeric_(mode == ParameterMode::Numeric),
          table_(parameterTable(scene)),
          values_(exactValues(table_)) {
        const std::vector<Diagnostic> names = checkCoordinateNames(spec_.coordinates, table_);
        if (!names.empty()) throw InputError(names);
        if (n_ == 0) throw InputError("lagrangian.coordinates", MessageId::LagrangianNeedsCoordinate);
        if (scene.effects.gravity || !scene.effects.springs.empty())
            throw InputError(scene.effects.gravity ? "effects.gravity" : "effects.springs", MessageId::LagrangianGravityInPotential);
        if (!spec_.forces.empty() && static_cast<int>(spec_.forces.size()) != n_)
            throw InputError("lagrangian.forces", message(MessageId::ForcesOneEntryPerCoordinate, n_));
        s_ = lagrangianSymbols(spec_.coordinates);
    }

    Derivation derive() {
        d_.system = SystemKind::Lagrangian;
        d_.systemName = scene_.name;
        for (const std::string& name : table_.names())  // parameters typed as decimals (9.8): shown as typed
            if (const ex& v = table_.definition(name); GiNaC::is_a<GiNaC::numeric>(v) && !GiNaC::ex_to<GiNaC::numeric>(v).is_rational())
                if (const ex x = exactNumber(table_.value(name)); !GiNaC::ex_to<GiNaC::numeric>(x).is_integer())
                    d_.typedDecimals.push_back(GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(x)));
        d_.q = s_.q;
        d_.qd = s_.qd;
        d_.qdd = s_.qdd;
        d_.t = s_.t;
        d_.coordinateNames = spec_.coordinates;
        if (!numeric_) d_.parameterValues = toList(values_);

        readExpressions();
        // The input checks run on the expressions as written (parameters kept, so the
        // messages show them), and all of them before anything is derived.
        std::vector<Diagnostic> errors = conservativeForces();
        if (auto kinetic = kineticEnergyError()) errors.push_back(*kinetic);
        if (!errors.empty()) throw InputError(errors);
        stepCoordinates();
        stepPotential();
        stepKinetic();
        checkPositiveDefinite();
        stepEquations();
        return std::move(d_);
    }

private:
    // As written, and in the mode's form (numbers substituted in Numeric mode).
    std::pair<ex, ex> parse(const std::string& field, const std::string& text, LagrangianField kind) const {
        const ex e = parseLagrangianField(table_, s_, field, text, kind);
        return {e, numeric_ ? e.subs(values_) : e};
    }

    void readExpressions() {
        std::tie(written_.Ekin, Ekin_) = parse("lagrangian.kinetic", spec_.kinetic, LagrangianField::Kinetic);
        std::tie(written_.Epot, Epot_) =
            parse("lagrangian.potential", spec_.potential.empty() ? "0" : spec_.potential, LagrangianField::Potential);
        forces_ = written_.forces = matrix(n_, 1);
        for (int i = 0; i < static_cast<int>(spec_.forces.size()); ++i)
            std::tie(written_.forces(i, 0), forces_(i, 0)) = parse(lagrangianForceField(i), spec_.forces[i], LagrangianField::Force);
    }

    // A component that depends on q alone, with ∂Q_i/∂q_j = ∂Q_j/∂q_i for every j, is
    // (locally) −∂V/∂q_i of a potential V: conservative, so it belongs in E_pot.
    std::vector<Diagnostic> conservativeForces() const {
        const matrix& forces = written_.forces;
        std::vector<int> conservative;
        for (int i = 0; i < n_; ++i) {
            const ex& F = forces(i, 0);
            const bool onCoordinates = std::any_of(s_.q.begin(), s_.q.end(), [&](const auto& q) { return F.has(q); });
            const bool onVelocities = std::any_of(s_.qd.begin(), s_.qd.end(), [&](const auto& v) { return F.has(v); });
            if (!onCoordinates || onVelocities || F.has(s_.t)) continue;
            bool symmetric = true;
            for (int j = 0; j < n_ && symmetric; ++j) symmetric = j == i || isZero(F.diff(s_.q[j]) - forces(j, 0).diff(s_.q[i]));
            if (symmetric) conservative.push_back(i);
        }
        if (conservative.empty()) return {};
        // The potential of those components, V = −∫₀¹ Σ Q_j(s q) q_j ds, when it integrates.
        GiNaC::symbol s("s");
        GiNaC::exmap scaled;
        for (const GiNaC::symbol& q : s_.q) scaled[q] = s * q;
        ex integrand = 0;
        for (int j : conservative) integrand -= forces(j, 0).subs(scaled) * s_.q[j];
        integrand = integrand.expand();
        Message potential;  // " (Q = -dV/dq with V = ...)", or nothing
        if (integrand.is_polynomial(s)) {
            ex V = 0;
            for (int k = integrand.ldegree(s); k <= integrand.degree(s); ++k) V += integrand.coeff(s, k) / (k + 1);
            potential = message(MessageId::ConservativeForcePotential, str(V.normal()));
        }
        std::vector<Diagnostic> errors;
        for (int i : conservative)
            errors.push_back(
                {Severity::Error, lagrangianForceField(i), message(MessageId::ConservativeForce, i + 1, spec_.forces[i], potential)});
        return errors;
    }

    // E_kin must be ½ q̇ᵀ B(q) q̇ exactly, with b_ij = ∂²E_kin/∂q̇_i∂q̇_j free of q̇.
    std::optional<Diagnostic> kineticEnergyError() const {
        using enum MessageId;
        const ex& Ekin = written_.Ekin;
        ex quadratic = 0;
        for (int i = 0; i < n_; ++i)
            for (int j = 0; j < n_; ++j) {
                const ex b = simplified(Ekin.diff(s_.qd[i]).diff(s_.qd[j]));
                for (const GiNaC::symbol& v : s_.qd)
                    if (b.has(v))
                        return Diagnostic{Severity::Error, "lagrangian.kinetic",
                                          message(KineticNotQuadratic, spec_.kinetic, s_.qd[i].get_name(), s_.qd[j].get_name(),
                                                  v.get_name())};
                quadratic += GiNaC::numeric(1, 2) * b * s_.qd[i] * s_.qd[j];
            }
        const ex rest = simplified(Ekin - quadratic).normal();
        if (rest.is_zero()) return std::nullopt;
        std::string left = str(rest);
        if (left.size() > 60) left = left.substr(0, 57) + "...";
        return Diagnostic{Severity::Error, "lagrangian.kinetic", message(KineticNotQuadraticForm, left),
                          message(KineticLeftOverHint, spec_.kinetic)};
    }

    void addStep(int number, Message title, StepFormula formula, std::vector<DerivationItem> items) {
        const auto now = std::chrono::steady_clock::now();
        const double seconds = std::chrono::duration<double>(now - lap_).count();
        lap_ = now;
        d_.steps.push_back({number, std::move(title), std::move(formula), std::move(items), seconds});
    }

    void stepCoordinates() {
        matrix q(n_, 1), qd(n_, 1);
        for (int i = 0; i < n_; ++i) {
            q(i, 0) = s_.q[i];
            qd(i, 0) = s_.qd[i];
        }
        addStep(0, MessageId::TitleGeneralizedCoordinates,
                stepFormula("q = (q_1, …, q_n): «1»;  «2»", R"(q = (q_1, \dots, q_n)\ «1»,\quad \dot{q} = \frac{dq}{dt};\quad «2»)",
                            {formulaWords(MessageId::FormulaCoordinatesChosen, {"ẋ = dx/dt"}), formulaWords(MessageId::FormulaRobotStepsAbsent)},
                            {formulaWords(MessageId::FormulaCoordinatesChosenShort), formulaWords(MessageId::FormulaRobotStepsAbsent)}),
                {{"q", Quantity::Coordinates, -1, Grouping::Parameters, q}, {"qd", Quantity::Velocities, -1, Grouping::Parameters, qd}});
    }

    void stepPotential() {
        d_.Epot = Epot_;
        addStep(6, MessageId::TitlePotentialEnergy,
                stepFormula("E_pot(q) «1»", R"(E_{\mathrm{pot}}(q))", {formulaWords(MessageId::FormulaPotentialAsGiven)}),
                {{"E_pot", Quantity::PotentialEnergy, -1, Grouping::Parameters, Epot_}});
    }

    void stepKinetic() {
        // b_ij = ∂²E_kin/∂q̇_i∂q̇_j (checked: free of q̇, and ½ q̇ᵀ B q̇ = E_kin).
        d_.B = matrix(n_, n_);
        for (int i = 0; i < n_; ++i)
            for (int j = i; j < n_; ++j) {
                d_.B(i, j) = simplified(Ekin_.diff(s_.qd[i]).diff(s_.qd[j]));
                d_.B(j, i) = d_.B(i, j);
            }
        d_.Ekin = Ekin_;
        addStep(
            7, MessageId::TitleKineticEnergy,
            stepFormula(
                "E_kin(q, q̇) «1» = ½ q̇ᵀ «B»(«q») q̇,  «b»_ij = ∂²E_kin/(∂q̇_i ∂q̇_j)",
                R"(E_{\mathrm{kin}} = \tfrac{1}{2}\,\dot{q}^T «B»(«q»)\,\dot{q},\quad «b»_{ij} = \frac{\partial^2 E_{\mathrm{kin}}}{\partial \dot{q}_i\,\partial \dot{q}_j})",
                {formulaWords(MessageId::FormulaAsGiven)}),
            {{"E_kin", Quantity::KineticEnergy, -1, Grouping::Velocities, Ekin_},
             {"B", Quantity::MassMatrix, -1, Grouping::Parameters, d_.B}});
    }

    // B(q0) must be positive definite: otherwise some motion of the coordinates moves no
    // mass, i.e. they are not independent (x and 2x) or not minimal.
    void checkPositiveDefinite() {
        using enum MessageId;
        GiNaC::exmap at = values_;
        Eigen::VectorXd q0 = Eigen::VectorXd::Zero(n_);
        if (scene_.initial.q.size() == n_) q0 = scene_.initial.q;
        for (int i = 0; i < n_; ++i) at[s_.q[i]] = exactNumber(q0[i]);
        std::string where = "q = [";
        for (int i = 0; i < n_; ++i) where += (i ? ", " : "") + number(q0[i]);
        where += "]";
        Eigen::MatrixXd B0(n_, n_);
        for (int i = 0; i < n_; ++i)
            for (int j = 0; j < n_; ++j) {
                ex value;
                try {
                    value = d_.B(i, j).subs(at).evalf();
                } catch (const std::exception& e) {
                    throw InputError("lagrangian.kinetic", message(InitialMassMatrixNotEvaluable, where, e.what()));
                }
                if (!GiNaC::is_a<GiNaC::numeric>(value) || !GiNaC::ex_to<GiNaC::numeric>(value).is_real())
                    throw InputError("lagrangian.kinetic", message(InitialMassEntryNotReal, i + 1, j + 1, str(d_.B(i, j)), where));
                B0(i, j) = GiNaC::ex_to<GiNaC::numeric>(value).to_double();
            }
        if (!B0.allFinite()) throw InputError("lagrangian.kinetic", message(InitialMassMatrixNotFinite, where));
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(B0);
        const Eigen::VectorXd& lambda = eigen.eigenvalues();
        const double scale = lambda.cwiseAbs().maxCoeff();
        if (scale > 0 && lambda[0] > 1e-12 * scale) return;
        Eigen::VectorXd v = eigen.eigenvectors().col(0);
        Eigen::Index largest;
        v.cwiseAbs().maxCoeff(&largest);
        v /= v[largest];
        std::string velocities = "(", values = "(", eigenvalues;
        for (int i = 0; i < n_; ++i) {
            const char* comma = i ? ", " : "";  // appended piece by piece (GCC 12's -Wrestrict misreads "" + string)
            velocities.append(comma).append(s_.qd[i].get_name());
            values.append(comma).append(number(v[i]));
            eigenvalues.append(comma).append(number(lambda[i]));
        }
        velocities += ")";
        values += ")";
        const bool negative = lambda[0] < -1e-12 * scale;
        throw InputError("lagrangian.coordinates", message(InitialMassMatrixNotPositiveDefinite, where),
                         message(MassMatrixEigenvalues, eigenvalues,
                                 message(negative ? VelocitiesGiveNegativeEnergy : VelocitiesMoveNoMass, velocities, values)));
    }

    void stepEquations() {
        std::vector<DerivationItem> items;
        const ex L = Ekin_ - Epot_;
        items.push_back({"L", Quantity::Lagrangian, -1, Grouping::Parameters, L});
        for (int i = 0; i < n_; ++i) {
            const std::string q = s_.q[i].get_name(), qd = s_.qd[i].get_name();
            const ex momentum = L.diff(s_.qd[i]);
            ex rate = 0;  // d/dt by the chain rule (E_kin and E_pot do not depend on t)
            for (int j = 0; j < n_; ++j) rate += momentum.diff(s_.q[j]) * s_.qd[j] + momentum.diff(s_.qd[j]) * s_.qdd[j];
            items.push_back({"dL/d" + qd, Quantity::MomentumPartial, i, Grouping::Parameters, momentum});
            items.push_back({"d/dt dL/d" + qd, Quantity::MomentumRate, i, Grouping::Parameters, rate.expand()});
            items.push_back({"dL/d" + q, Quantity::CoordinatePartial, i, Grouping::Parameters, L.diff(s_.q[i])});
        }

        d_.g = matrix(n_, 1);
        for (int i = 0; i < n_; ++i) d_.g(i, 0) = Epot_.diff(s_.q[i]);
        std::vector<matrix> dB(n_);
        for (int k = 0; k < n_; ++k) dB[k] = GiNaC::ex_to<matrix>(d_.B.diff(s_.q[k]));
        d_.C = matrix(n_, n_);
        christoffelMatrix<ex>(n_, dB, s_.qd, d_.C);
        for (int i = 0; i < n_; ++i)
            for (int j = 0; j < n_; ++j) d_.C(i, j) = simplified(d_.C(i, j));
        generalizedForces();

        items.push_back({"g", Quantity::GravityVector, -1, Grouping::Parameters, d_.g});
        items.push_back({"C", Quantity::CoriolisMatrix, -1, Grouping::Velocities, d_.C});
        items.push_back({"Q", Quantity::GeneralizedForces, -1, Grouping::Parameters, d_.Q});
        for (int i = 0; i < n_; ++i) {
            ex lhs = d_.g(i, 0);
            for (int j = 0; j < n_; ++j) lhs += d_.B(i, j) * s_.qdd[j] + d_.C(i, j) * s_.qd[j];
            const std::string k = std::to_string(i + 1);
            items.push_back({"equation_" + k, Quantity::EquationOfMotion, i, Grouping::Parameters, lhs == d_.Q(i, 0)});
        }
        addStep(
            8, MessageId::TitleEquationsOfMotion,
            stepFormula(
                "L = E_kin − E_pot;  d/dt ∂L/∂q̇_i − ∂L/∂q_i = «Q»_i;  «1»;  q̈ = «B»⁻¹ («Q» − C q̇ − «g»)",
                R"(\mathcal{L} = E_{\mathrm{kin}} - E_{\mathrm{pot}},\quad \frac{d}{dt}\frac{\partial \mathcal{L}}{\partial \dot{q}_i} - \frac{\partial \mathcal{L}}{\partial q_i} = «Q»_i,\quad «g» = \frac{\partial E_{\mathrm{pot}}}{\partial q},\quad c_{ij} = \sum_k \tfrac{1}{2}\left(\frac{\partial «b»_{ij}}{\partial q_k} + \frac{\partial «b»_{ik}}{\partial q_j} - \frac{\partial «b»_{jk}}{\partial q_i}\right)\dot{q}_k,\quad «B»\ddot{q} + C\dot{q} + «g» = «Q»)",
                {formulaWordsOf(MessageId::FormulaWrittenAs,
                                {formulaPieces("«B» q̈ + C q̇ + «g» = «Q»"),
                                 formulaPieces("«g» = ∂E_pot/∂q, c_ij = Σ_k ½ (∂«b»_ij/∂q_k + ∂«b»_ik/∂q_j − ∂«b»_jk/∂q_i) q̇_k, «Q»: «1»",
                                               {formulaWords(MessageId::FormulaNonConservativeOnly)})})}),
            items);
    }

    // Q = the `forces` plus the declared torques and friction (by coordinate). The
    // effects are read as for a robot, then their parameter symbols are made ours.
    void generalizedForces() {
        d_.Q = forces_;
        const SymbolicRobot effects = symbolicRobot(scene_, numeric_ ? ParameterMode::Numeric : ParameterMode::Parametric, s_.t);
        GiNaC::exmap ours;
        for (const ex& relation : effects.parameterValues) {
            const ex& theirs = relation.lhs();
            if (GiNaC::is_a<GiNaC::symbol>(theirs) && table_.contains(GiNaC::ex_to<GiNaC::symbol>(theirs).get_name()))
                ours[theirs] = table_.symbol(GiNaC::ex_to<GiNaC::symbol>(theirs).get_name());
        }
        d_.Q = d_.Q.add(GiNaC::ex_to<matrix>(effectForces(effects, s_.qd).subs(ours)));

        // Inputs: declared torques, and forces that do not vanish at rest (friction does).
        GiNaC::exmap rest;
        for (const GiNaC::symbol& v : s_.qd) rest[v] = 0;
        for (const SymbolicTerm& torque : effects.torques) d_.actuated.push_back(torque.joint);
        for (int i = 0; i < n_; ++i) {
            ex atRest;
            try {
                atRest = forces_(i, 0).subs(rest);
            } catch (const GiNaC::pole_error&) {  // -0.1/theta1_dot: no force is infinite at rest
                throw InputError(lagrangianForceField(i), message(MessageId::ForceInfiniteAtRest, spec_.forces[i]));
            }
            if (!isZero(atRest)) d_.actuated.push_back(i);
        }
        std::sort(d_.actuated.begin(), d_.actuated.end());
        d_.actuated.erase(std::unique(d_.actuated.begin(), d_.actuated.end()), d_.actuated.end());
        d_.underactuated = static_cast<int>(d_.actuated.size()) < n_;
    }

    const Scene& scene_;
    const LagrangianSpec& spec_;
    const int n_;
    const bool numeric_;
    const ParameterTable table_;
    const GiNaC::exmap values_;
    LagrangianSymbols s_;
    struct Written {  // the expressions as the user wrote them, parameters kept
        ex Ekin, Epot;
        matrix forces;
    } written_;
    ex Ekin_, Epot_;  // in the derivation's mode
    matrix forces_;
    Derivation d_;
    std::chrono::steady_clock::time_point lap_ = std::chrono::steady_clock::now();
};

}  // namespace

Derivation deriveLagrangian(const Scene& scene, ParameterMode mode) {
    const auto lock = lockGinac();
    if (!scene.lagrangian) throw std::invalid_argument("deriveLagrangian: the scene has no \"lagrangian\" block");
    return LagrangianDeriver(scene, mode).derive();
}

}  // namespace ll::symbolic
