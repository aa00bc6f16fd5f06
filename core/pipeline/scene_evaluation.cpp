#include "core/pipeline/scene_evaluation.hpp"

#include "core/math/cholesky.hpp"
#include "core/dynamics/finite_terms.hpp"
#include "core/dynamics/forward_dynamics.hpp"
#include "core/model/actuation.hpp"
#include "core/model/diagnostics.hpp"
#include "core/simulation/generalized_forces.hpp"
#include "core/simulation/robot_terms.hpp"
#include "core/symbolic/compiled_derivation.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/lagrangian_derivation.hpp"

namespace ll {
namespace {

// A Lagrangian system: its derivation, compiled once. With tau the inputs (what Q is at
// rest) are replaced and friction (what vanishes at rest) stays.
SceneEvaluation evaluateLagrangian(const Scene& scene, const Eigen::VectorXd& q, const Eigen::VectorXd& qd, double t,
                                   const std::optional<Eigen::VectorXd>& tau) {
    const int n = scene.dof();
    SceneEvaluation out;
    const auto lock = symbolic::lockGinac();  // the derivation is GiNaC objects
    const symbolic::Derivation d = symbolic::deriveLagrangian(scene, symbolic::ParameterMode::Numeric);
    const CompiledLagrangian model = symbolic::compileDerivation(d);
    out.terms = model.terms(q, qd, t);
    if (tau) out.terms.Q += *tau - model.terms(q, Eigen::VectorXd::Zero(n), t).Q;
    out.actuated = d.actuated;
    out.underactuated = d.underactuated;
    out.coordinates = d.coordinateNames;
    if (auto bad = nonFiniteTerm(out.terms, Eigen::VectorXd(), q, qd, message(MessageId::WhereAtTime, t))) throw InputError({*bad});
    const ModelTerms& m = out.terms;
    Cholesky llt(n);
    if (llt.compute(m.B).info() != Eigen::Success)
        throw InputError("q", message(MessageId::MassMatrixNotPositiveDefiniteHere, MessageId::CoordinatesNotIndependentHere));
    out.qdd = llt.solve(m.Q - m.C * qd - m.g);
    return out;
}

}  // namespace

SceneEvaluation evaluateScene(const Scene& scene, const Eigen::VectorXd& q, const Eigen::VectorXd& qd, double t,
                              const std::optional<Eigen::VectorXd>& tau) {
    SceneEvaluation out;
    if (scene.lagrangian) {
        out = evaluateLagrangian(scene, q, qd, t, tau);
    } else {
        try {
            RobotEvaluation e = evaluateRobot(scene, q, qd, t, tau);
            out.terms = std::move(e.terms);
            out.qdd = std::move(e.qdd);
        } catch (const SingularMassMatrix& e) {
            throw InputError("q", message(MessageId::MassMatrixNotPositiveDefiniteHere,
                                          message(MessageId::MassMatrixSingularAtJoint, e.joint() + 1)));  // e.what() in words
        }
        out.actuated = actuatedJoints(scene.effects, scene.dof());
        out.underactuated = static_cast<int>(out.actuated.size()) < scene.dof();
    }
    if (tau) {  // every coordinate has an input
        out.actuated.clear();
        for (int i = 0; i < scene.dof(); ++i) out.actuated.push_back(i);
        out.underactuated = false;
    }
    if (auto bad = nonFiniteTerm(out.terms, out.qdd, q, qd, message(MessageId::WhereAtTime, t))) throw InputError({*bad});
    if (out.qdd.size() != scene.dof())  // evaluateRobot leaves qdd empty when a term is not finite
        throw InputError("qdd", MessageId::AccelerationNotComputed);
    return out;
}

}  // namespace ll
