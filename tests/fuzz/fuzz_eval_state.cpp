// libFuzzer: eval of a loaded example at a fuzzed state. The first byte picks the scene,
// the rest are read as doubles (any bit pattern: NaN, inf, subnormal, huge) for q, q̇,
// t and, when a byte says so, τ. Every answer is finite, or InputError names what.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

#include "core/io/scene_file.hpp"
#include "core/pipeline/scene_evaluation.hpp"
#include "fuzz_support.hpp"

namespace {

const std::vector<ll::Scene>& scenes() {
    static const std::vector<ll::Scene> all = [] {
        std::vector<ll::Scene> s;
        for (const char* name : {"planar_2r.json", "puma560.json", "mass_spring_pair.json", "cart_pole.json",
                                 "mass_spring_pair_lagrangian.json", "elastic_pendulum.json", "stanford_arm.json", "hard/stick_slip.json"})
            s.push_back(ll::loadScene(std::string(LL_EXAMPLES_DIR) + "/" + name).scene);
        return s;
    }();
    return all;
}

}  // namespace

int ll::fuzz::evalState(const std::uint8_t* data, std::size_t size) {
    if (size < 2) return 0;
    const ll::Scene& scene = scenes()[data[0] % scenes().size()];
    const bool withTau = data[1] & 1;
    const int n = scene.dof();
    std::vector<double> values((size - 2) / sizeof(double));
    if (!values.empty()) std::memcpy(values.data(), data + 2, values.size() * sizeof(double));
    std::size_t next = 0;
    const auto take = [&](double fallback) { return next < values.size() ? values[next++] : fallback; };
    Eigen::VectorXd q(n), qd(n), tau(n);
    for (int i = 0; i < n; ++i) q[i] = take(scene.initial.q[i]);
    for (int i = 0; i < n; ++i) qd[i] = take(0.0);
    const double t = take(0.0);
    for (int i = 0; i < n; ++i) tau[i] = take(0.0);
    // The CLI refuses non-finite options (cli_options); the core gets finite inputs.
    const auto finite = [](const Eigen::VectorXd& v) { return v.allFinite(); };
    if (!finite(q) || !finite(qd) || !finite(tau) || !std::isfinite(t)) return 0;
    try {
        const ll::SceneEvaluation e = ll::evaluateScene(scene, q, qd, t, withTau ? std::optional<Eigen::VectorXd>(tau) : std::nullopt);
        ll::fuzz::require(e.terms.B.allFinite() && e.terms.C.allFinite() && e.terms.g.allFinite() && e.terms.Q.allFinite() &&
                              e.qdd.allFinite() && std::isfinite(e.terms.Ekin) && std::isfinite(e.terms.Epot),
                          "eval returned a non-finite number");
    } catch (const ll::InputError& e) {
        ll::fuzz::checkRefusal(e);
    }
    return 0;
}
