#include "core/simulation/torque_parts.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <stdexcept>

#include "core/math/cholesky.hpp"
#include "core/dynamics/coriolis.hpp"
#include "core/dynamics/forward_dynamics.hpp"
#include "core/dynamics/potential_gradient.hpp"
#include "core/model/friction_law.hpp"
#include "core/simulation/generalized_forces.hpp"

namespace ll {
namespace {

// The parts from B, C q̇, g and Q's pieces: q̈ solves B q̈ = Q − C q̇ − g.
void complete(TorqueParts& p, const Eigen::MatrixXd& B, const Eigen::VectorXd& Cqd, const Eigen::VectorXd& g) {
    p.coriolis = Cqd;
    p.potential = g;
    Cholesky llt(static_cast<int>(B.rows()));
    if (llt.compute(B).info() != Eigen::Success)
        throw SingularMassMatrix(firstSingularJoint(B), "torqueHistory: B(q) is not positive definite");
    p.qdd = llt.solve(p.Q() - Cqd - g);
    p.inertial = B * p.qdd;
}

}  // namespace

double TorqueParts::residual() const { return (inertial + coriolis + potential - Q()).cwiseAbs().maxCoeff(); }

TorqueHistory torqueHistory(const SimulationInput& input, const Trajectory& trajectory) {
    const Scene& scene = input.scene;
    const int n = scene.dof();
    if (trajectory.n != n)
        throw std::invalid_argument("torqueHistory: the trajectory has " + std::to_string(trajectory.n) + " coordinates, the scene " +
                                    std::to_string(n));
    if (scene.lagrangian && !input.lagrangian) throw std::invalid_argument("torqueHistory: a Lagrangian scene needs its compiled system");
    TorqueHistory history;
    history.t = trajectory.t;
    history.parts.reserve(trajectory.size());
    std::optional<RobotData> data;
    if (!scene.lagrangian) data.emplace(scene.robot);
    const Effects& effects = scene.effects;
    for (std::size_t k = 0; k < trajectory.size(); ++k) {
        const Eigen::VectorXd& q = trajectory.q[k];
        const Eigen::VectorXd& qd = trajectory.qd[k];
        const double t = trajectory.t[k];
        TorqueParts p;
        p.viscous = p.coulomb = Eigen::VectorXd::Zero(n);
        if (scene.lagrangian) {
            const ModelTerms terms = input.lagrangian->terms(q, qd, t);
            p.actuation = terms.Q;
            complete(p, terms.B, terms.C * qd, terms.g);
        } else {
            const RobotModel& robot = scene.robot;
            p.actuation = Eigen::VectorXd::Zero(n);
            computeExternalTorques(effects, t, p.actuation);
            addControlTorques(robot, effects, t, q, qd, p.actuation);
            for (const ViscousFriction& f : effects.viscous) p.viscous[f.joint] += viscousFrictionForce(f.coefficient, qd[f.joint]);
            for (const CoulombFriction& f : effects.coulomb) {
                const double v = qd[f.joint];
                p.coulomb[f.joint] +=
                    f.model == CoulombModel::Tanh ? tanhCoulombForce(f.force, v, f.smoothing) : -f.force * ((v > 0) - (v < 0));
            }
            // q̈ as the simulation computes it (C q̇ + g by recursive Newton–Euler), the
            // parts from the Lagrangian route (Christoffel symbols, the potential's gradient):
            // the residual is the two routes' disagreement.
            p.qdd = forwardDynamics(robot, *data, effects, q, qd, p.Q());
            computeCoriolisMatrix(robot, *data, qd);
            computePotentialGradient(robot, *data, effects, q);
            p.inertial = data->B * p.qdd;
            p.coriolis = data->C * qd;
            p.potential = data->g;
        }
        history.largestResidual = std::max(history.largestResidual, p.residual());
        for (const Eigen::VectorXd* v : {&p.inertial, &p.coriolis, &p.potential})
            history.scale = std::max(history.scale, v->cwiseAbs().maxCoeff());
        history.scale = std::max(history.scale, p.Q().cwiseAbs().maxCoeff());
        history.parts.push_back(std::move(p));
    }
    return history;
}

}  // namespace ll
