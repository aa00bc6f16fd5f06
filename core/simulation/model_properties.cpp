#include "core/simulation/model_properties.hpp"

#include "core/math/cholesky.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "core/dynamics/coriolis.hpp"
#include "core/dynamics/energy.hpp"
#include "core/dynamics/inverse_dynamics.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/dynamics/potential_gradient.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/model/quantity_units.hpp"
#include "core/simulation/generalized_forces.hpp"

namespace ll {
namespace {

// The model's terms at one state, whichever way the scene is given.
struct Terms {
    Eigen::MatrixXd B, C, Bdot;
    Eigen::VectorXd g, Q, rnea;  // rnea: empty for a typed Lagrangian
};

class Model {
public:
    explicit Model(const SimulationInput& input) : input_(input) {
        if (!input.scene.lagrangian) data_.emplace(input.scene.robot);
    }
    bool robot() const { return data_.has_value(); }

    Terms at(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, double t) {
        Terms r;
        const int n = static_cast<int>(q.size());
        if (robot()) {
            const RobotModel& model = input_.scene.robot;
            RobotData& d = *data_;
            forwardKinematics(model, d, q);
            computeMassMatrix(model, d);
            computeCoriolisMatrix(model, d, qd);  // fills dB_dq too
            computePotentialGradient(model, d, input_.scene.effects, q);
            r.B = d.B, r.C = d.C, r.g = d.g;
            r.Bdot = Eigen::MatrixXd::Zero(n, n);
            for (int k = 0; k < n; ++k) r.Bdot += d.dB_dq[k] * qd[k];
            r.Q = Eigen::VectorXd::Zero(n);
            computeGeneralizedForces(input_.scene.effects, t, qd, r.Q);
            addControlTorques(model, input_.scene.effects, t, q, qd, r.Q);
            return r;
        }
        const CompiledLagrangian& L = *input_.lagrangian;
        const ModelTerms m = L.terms(q, qd, t);
        r.B = m.B, r.C = m.C, r.g = m.g, r.Q = m.Q;
        // Ḃ = Σ_k ∂B/∂q_k q̇_k = d/dh B(q + h q̇) at h = 0, by central differences.
        const double h = 1e-6 / std::max(1.0, qd.norm());
        r.Bdot = (L.terms(q + h * qd, qd, t).B - L.terms(q - h * qd, qd, t).B) / (2 * h);
        return r;
    }

    // τ by recursive Newton–Euler (robots).
    Eigen::VectorXd rnea(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, const Eigen::VectorXd& qdd) {
        return inverseDynamics(input_.scene.robot, *data_, input_.scene.effects, q, qd, qdd);
    }

private:
    const SimulationInput& input_;
    std::optional<RobotData> data_;
};

PropertyCheck check(std::string key, std::string title, std::string explanation, double tolerance, bool atLeast = false,
                    std::string unit = "") {
    PropertyCheck c;
    c.key = std::move(key);
    c.title = std::move(title);
    c.explanation = std::move(explanation);
    c.tolerance = tolerance;
    c.atLeast = atLeast;
    c.unit = std::move(unit);
    c.value = atLeast ? std::numeric_limits<double>::infinity() : 0.0;
    return c;
}

// Keeps the worst value and where it was.
void worst(PropertyCheck& c, double value, double t, const Eigen::VectorXd& q) {
    if (!std::isfinite(value) || (c.atLeast ? value < c.value : value > c.value)) {
        c.value = value;
        c.time = t;
        c.q = q;
    }
}

// B's unit when all its entries share one (all joints revolute or all prismatic), else "".
std::string massMatrixUnitOf(const Scene& scene) {
    if (scene.lagrangian || scene.robot.joints.empty()) return "";
    const bool revolute = scene.robot.joints[0].dh.type == JointType::Revolute;
    for (const Joint& j : scene.robot.joints)
        if ((j.dh.type == JointType::Revolute) != revolute) return "";
    return massMatrixUnit(revolute, revolute);
}

}  // namespace

bool ModelProperties::passed() const {
    return std::all_of(checks.begin(), checks.end(), [](const PropertyCheck& c) { return !c.applies || c.passed; });
}

const PropertyCheck* ModelProperties::find(const std::string& key) const {
    for (const PropertyCheck& c : checks)
        if (c.key == key) return &c;
    return nullptr;
}

ModelProperties checkModelProperties(const SimulationInput& input, const Trajectory& trajectory) {
    const int n = input.scene.dof();
    if (trajectory.size() == 0) throw std::invalid_argument("checkModelProperties: the trajectory is empty");
    if (trajectory.n != n) throw std::invalid_argument("checkModelProperties: the trajectory does not fit the scene");
    if (input.scene.lagrangian && !input.lagrangian)
        throw std::invalid_argument("checkModelProperties: a Lagrangian scene needs its compiled system");
    Model model(input);
    const bool robot = model.robot();
    const double derivativeTolerance = robot ? 1e-9 : 1e-6;  // exact ∂B/∂q, or central differences

    PropertyCheck eigen = check("min_eigenvalue_B", "B is positive definite",
                                "Its smallest eigenvalue stays above zero, so the kinetic energy ½ q̇ᵀBq̇ is positive for "
                                "any motion and B q̈ = Q − C q̇ − g has one solution.",
                                0.0, true, massMatrixUnitOf(input.scene));
    PropertyCheck condition = check("max_condition_B", "B is well conditioned",
                                    "Its largest over smallest eigenvalue stays below 10⁸, so solving for q̈ keeps at least "
                                    "half of the 16 digits a double carries.",
                                    1e8);
    PropertyCheck skew = check("skew_residual", "Ḃ − 2C is skew-symmetric",
                               "xᵀ(Ḃ − 2C)x = 0 for every x: the Coriolis and centrifugal forces C q̇ do no work, they only "
                               "turn the motion.",
                               derivativeTolerance, false, "1/s");
    PropertyCheck power = check("power_balance_residual", "Power balance dE/dt = q̇ᵀQ",
                                "The energy changes only by the power of the non-conservative forces Q (friction, "
                                "torques): gravity and springs are inside E, C q̇ does no work.",
                                derivativeTolerance);
    PropertyCheck newton = check("newton_euler_residual", "Newton–Euler agrees",
                                 "The recursive Newton–Euler algorithm, which never forms B or C, gives the same joint "
                                 "torques B q̈ + C q̇ + g: the Lagrangian derivation is right.",
                                 1e-9);
    newton.applies = robot;
    PropertyCheck energy = check("energy_error", "Energy balance along the run",
                                 "E − E₀ equals the work W done by the non-conservative forces at every sample: the "
                                 "integrator kept the energy as the model says.",
                                 1e-4);

    std::mt19937 rng(4711);
    std::normal_distribution<double> normal;
    double powerScale = 0.0, largestPower = 0.0, torqueScale = 0.0, largestTorqueError = 0.0;
    double tPower = 0, tTorque = 0;
    Eigen::VectorXd qPower, qTorque;
    double energyScale = 0.0, largestEnergyError = 0.0, tEnergy = 0;
    Eigen::VectorXd qEnergy;
    const double E0 = trajectory.E.front(), Epot0 = trajectory.Epot.front();
    for (std::size_t k = 0; k < trajectory.size(); ++k) {
        const Eigen::VectorXd& q = trajectory.q[k];
        const Eigen::VectorXd& qd = trajectory.qd[k];
        const double t = trajectory.t[k];
        const Terms m = model.at(q, qd, t);
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigenvalues(m.B, Eigen::EigenvaluesOnly);
        const double lo = eigenvalues.eigenvalues()(0), hi = eigenvalues.eigenvalues()(n - 1);
        worst(eigen, lo, t, q);
        worst(condition, lo > 0 ? hi / lo : std::numeric_limits<double>::infinity(), t, q);

        const double Bnorm = m.B.norm();
        const Eigen::MatrixXd N = m.Bdot - 2 * m.C;
        for (int r = 0; r < 4; ++r) {
            Eigen::VectorXd x(n);
            for (int i = 0; i < n; ++i) x[i] = normal(rng);
            worst(skew, std::abs(x.dot(N * x)) / (x.squaredNorm() * Bnorm), t, q);
        }

        Cholesky llt(n);
        llt.compute(m.B);
        const Eigen::VectorXd qdd = llt.solve(m.Q - m.C * qd - m.g);
        // dE/dt from E = ½ q̇ᵀBq̇ + E_pot: q̇ᵀB q̈ + ½ q̇ᵀḂq̇ + gᵀq̇, against q̇ᵀQ.
        const double kinetic = qd.dot(m.B * qdd), bdot = 0.5 * qd.dot(m.Bdot * qd), potential = m.g.dot(qd), input = qd.dot(m.Q);
        powerScale = std::max({powerScale, std::abs(kinetic), std::abs(bdot), std::abs(potential), std::abs(input)});
        if (const double e = std::abs(kinetic + bdot + potential - input); e > largestPower || k == 0) {
            largestPower = e, tPower = t, qPower = q;
        }
        if (robot) {
            const Eigen::VectorXd lagrange = m.B * qdd + m.C * qd + m.g;
            const Eigen::VectorXd tau = model.rnea(q, qd, qdd);
            // The scale: the terms', not their sum's (which is Q, zero for an arm left to fall).
            torqueScale = std::max({torqueScale, (m.B * qdd).cwiseAbs().maxCoeff(), (m.C * qd).cwiseAbs().maxCoeff(),
                                    m.g.cwiseAbs().maxCoeff(), m.Q.cwiseAbs().maxCoeff()});
            if (const double e = (tau - lagrange).cwiseAbs().maxCoeff(); e > largestTorqueError || k == 0) {
                largestTorqueError = e, tTorque = t, qTorque = q;
            }
        }
        energyScale = std::max({energyScale, trajectory.Ekin[k], std::abs(trajectory.Epot[k] - Epot0), std::abs(trajectory.work[k])});
        if (const double e = std::abs(trajectory.E[k] - E0 - trajectory.work[k]); e > largestEnergyError || k == 0) {
            largestEnergyError = e, tEnergy = t, qEnergy = q;
        }
    }
    const auto relative = [](double error, double scale) { return scale > 0 ? error / scale : error; };
    worst(power, relative(largestPower, powerScale), tPower, qPower);
    if (robot) worst(newton, relative(largestTorqueError, torqueScale), tTorque, qTorque);
    worst(energy, relative(largestEnergyError, energyScale), tEnergy, qEnergy);

    ModelProperties out;
    for (PropertyCheck* c : {&eigen, &condition, &skew, &power, &newton, &energy}) {
        if (c->applies) c->passed = std::isfinite(c->value) && (c->atLeast ? c->value > c->tolerance : c->value <= c->tolerance);
        out.checks.push_back(*c);
    }
    return out;
}

}  // namespace ll
