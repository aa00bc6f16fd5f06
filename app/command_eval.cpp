// `lagrangelab eval SCENE --q ... --qd ... [--t T] [--tau ...]`: every term of
// B q̈ + C q̇ + g = Q at one state, as one JSON object.
#include <iostream>

#include <Eigen/Cholesky>

#include <nlohmann/json.hpp>

#include "app/cli_options.hpp"
#include "app/command_usage.hpp"
#include "app/commands.hpp"
#include "app/scene_loading.hpp"
#include "core/dynamics/coriolis.hpp"
#include "core/dynamics/energy.hpp"
#include "core/dynamics/forward_dynamics.hpp"
#include "core/dynamics/potential_gradient.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/model/diagnostics.hpp"
#include "core/simulation/generalized_forces.hpp"
#include "core/symbolic/compiled_derivation.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/lagrangian_derivation.hpp"

namespace ll::cli {
namespace {

nlohmann::json toJson(const Eigen::MatrixXd& M) {
    nlohmann::json rows = nlohmann::json::array();
    for (int r = 0; r < M.rows(); ++r) {
        nlohmann::json row = nlohmann::json::array();
        for (int c = 0; c < M.cols(); ++c) row.push_back(M(r, c));
        rows.push_back(row);
    }
    return rows;
}

nlohmann::json toJson(const Eigen::VectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); }

// A Lagrangian system: the same keys from its derivation, compiled once. With --tau the
// inputs (what Q is at rest) are replaced and friction (what vanishes at rest) stays.
int evalLagrangian(const Scene& scene, const Options& options) {
    const int n = scene.dof();
    const Eigen::VectorXd q = options.has("q") ? options.vector("q", n) : scene.initial.q;
    const Eigen::VectorXd qd = options.has("qd") ? options.vector("qd", n) : scene.initial.qd;
    const double t = options.number("t", 0.0);
    const auto lock = symbolic::lockGinac();  // the derivation is GiNaC objects
    const symbolic::Derivation d = symbolic::deriveLagrangian(scene, symbolic::ParameterMode::Numeric);
    const CompiledLagrangian model = symbolic::compileDerivation(d);
    ModelTerms m = model.terms(q, qd, t);
    if (options.has("tau")) m.Q += options.vector("tau", n) - model.terms(q, Eigen::VectorXd::Zero(n), t).Q;
    const Eigen::LLT<Eigen::MatrixXd> llt(m.B);
    if (llt.info() != Eigen::Success)
        throw InputError("--q", "the mass matrix B(q) is not positive definite at this state: the coordinates are "
                                "not independent here");
    const Eigen::VectorXd qdd = llt.solve(m.Q - m.C * qd - m.g);

    nlohmann::ordered_json out;
    out["B"] = toJson(m.B);
    out["C"] = toJson(m.C);
    out["g"] = toJson(m.g);
    out["Q"] = toJson(m.Q);
    out["qdd"] = toJson(qdd);
    out["Ekin"] = m.Ekin;
    out["Epot"] = m.Epot;
    out["t"] = t;
    if (!options.has("tau")) {
        std::vector<int> actuated;
        for (int j : d.actuated) actuated.push_back(j + 1);
        out["actuated_joints"] = actuated;
        out["underactuated"] = d.underactuated;
    }
    out["coordinates"] = d.coordinateNames;
    std::cout << out.dump(2) << '\n';
    return 0;
}

}  // namespace

int evalCommand(const Args& args) {
    const Options options(args, {"q", "qd", "t", "tau"});
    if (options.positional().size() != 1) throw UsageError(usageLine("eval"));
    const Scene scene = loadSceneReportingWarnings(options.positional()[0]);
    if (scene.lagrangian) return evalLagrangian(scene, options);
    const RobotModel& robot = scene.robot;
    const int n = robot.dof();
    const Eigen::VectorXd q = options.has("q") ? options.vector("q", n) : scene.initial.q;
    const Eigen::VectorXd qd = options.has("qd") ? options.vector("qd", n) : scene.initial.qd;
    const double t = options.number("t", 0.0);

    // Q: external torques (the scene's, or --tau in their place) plus friction at q̇.
    Eigen::VectorXd Q(n);
    if (options.has("tau"))
        Q = options.vector("tau", n);
    else
        computeExternalTorques(scene.effects, t, Q);
    addFrictionForces(scene.effects, qd, Q);

    RobotData data(robot);
    forwardKinematics(robot, data, q);
    computeMassMatrix(robot, data);
    computeCoriolisMatrix(robot, data, qd);
    computePotentialGradient(robot, data, scene.effects, q);
    const Eigen::MatrixXd B = data.B, C = data.C;
    const Eigen::VectorXd g = data.g;
    const double Ekin = kineticEnergy(data, qd), Epot = potentialEnergy(robot, data, scene.effects, q);
    const Eigen::VectorXd qdd = forwardDynamics(robot, data, scene.effects, q, qd, Q);

    nlohmann::ordered_json out;
    out["B"] = toJson(B);
    out["C"] = toJson(C);
    out["g"] = toJson(g);
    out["Q"] = toJson(Q);
    out["qdd"] = toJson(qdd);
    out["Ekin"] = Ekin;
    out["Epot"] = Epot;
    out["t"] = t;
    if (!options.has("tau")) {  // with --tau every joint has an input
        std::vector<int> actuated;
        for (int j : actuatedJoints(scene.effects, n)) actuated.push_back(j + 1);
        out["actuated_joints"] = actuated;
        out["underactuated"] = static_cast<int>(actuated.size()) < n;
    }
    std::cout << out.dump(2) << '\n';
    return 0;
}

}  // namespace ll::cli
