// `lagrangelab eval SCENE --q ... --qd ... [--t T] [--tau ...]`: every term of
// B q̈ + C q̇ + g = Q at one state, as one JSON object (core/pipeline/scene_evaluation).
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/cli_options.hpp"
#include "app/command_usage.hpp"
#include "app/commands.hpp"
#include "app/scene_loading.hpp"
#include "core/math/vector_list.hpp"
#include "core/pipeline/scene_evaluation.hpp"

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

nlohmann::json toJson(const Eigen::VectorXd& v) { return listOf(v); }

}  // namespace

int evalCommand(const Args& args) {
    const Options options(args, {"q", "qd", "t", "tau"});
    if (options.positional().size() != 1) throw UsageError(usageLine("eval"));
    const std::string& path = options.positional()[0];
    const Scene scene = loadSceneReportingWarnings(path);
    const int n = scene.dof();
    const Eigen::VectorXd q = options.has("q") ? options.vector("q", n) : scene.initial.q;
    const Eigen::VectorXd qd = options.has("qd") ? options.vector("qd", n) : scene.initial.qd;
    const double t = options.number("t", 0.0);
    std::optional<Eigen::VectorXd> tau;
    if (options.has("tau")) tau = options.vector("tau", n);
    // Errors name the quantity ("Epot", "qdd") or "q" after the file, like a field.
    const SceneEvaluation e = inSceneFile(path, [&] { return evaluateScene(scene, q, qd, t, tau); });

    nlohmann::ordered_json out;
    out["B"] = toJson(e.terms.B);
    out["C"] = toJson(e.terms.C);
    out["g"] = toJson(e.terms.g);
    out["Q"] = toJson(e.terms.Q);
    out["qdd"] = toJson(e.qdd);
    out["Ekin"] = e.terms.Ekin;
    out["Epot"] = e.terms.Epot;
    out["t"] = t;
    if (!tau) {  // with --tau every joint has an input
        std::vector<int> actuated;
        for (int j : e.actuated) actuated.push_back(j + 1);
        out["actuated_joints"] = actuated;
        out["underactuated"] = e.underactuated;
    }
    if (scene.lagrangian) out["coordinates"] = e.coordinates;
    std::cout << out.dump(2) << '\n';
    return 0;
}

}  // namespace ll::cli
