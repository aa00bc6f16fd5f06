// libFuzzer: the input's lines as a Lagrangian typed by hand (kinetic energy, potential
// energy, the two forces) in the course notes' mass–spring pair, through the reader,
// the checks (E_kin quadratic, B positive definite, no conservative force in Q), the
// derivation and evaluation at the initial state: finite numbers or InputError.
#include <cstdint>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "core/io/scene_file.hpp"
#include "core/pipeline/scene_check.hpp"
#include "core/pipeline/scene_evaluation.hpp"
#include "fuzz_support.hpp"

int ll::fuzz::lagrangian(const std::uint8_t* data, std::size_t size) {
    std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
    std::string field[4] = {"I1*theta1_dot^2/2 + I2*theta2_dot^2/2", "K1*theta1^2/2", "0", "tau"};
    for (std::string& f : field)
        if (!std::getline(lines, f)) break;
    nlohmann::ordered_json scene =
        {{"format", "lagrangelab-scene/1"},
         {"name", "fuzzed Lagrangian"},
         {"parameters", {{"I1", 0.5}, {"I2", 0.2}, {"K1", 10}, {"K2", 4}, {"tau", 1}}},
         {"lagrangian",
          {{"coordinates", {"theta1", "theta2"}}, {"kinetic", field[0]}, {"potential", field[1]}, {"forces", {field[2], field[3]}}}},
         {"initial", {{"q", {0.1, 0}}, {"qd", {0, 0.2}}}}};
    // Invalid UTF-8 in the lines: dump() would throw; the scene reader's own test covers it.
    const std::string text = scene.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    try {
        const ll::Scene parsed = ll::parseScene(text);
        if (ll::hasErrors(ll::checkScene(parsed))) return 0;
        const ll::SceneEvaluation e = ll::evaluateScene(parsed, parsed.initial.q, parsed.initial.qd, 0.0);
        ll::fuzz::require(e.qdd.allFinite() && std::isfinite(e.terms.Ekin + e.terms.Epot), "a non-finite result");
    } catch (const ll::InputError& e) {
        ll::fuzz::checkRefusal(e);
    }
    return 0;
}
