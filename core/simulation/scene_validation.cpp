#include "core/simulation/scene_validation.hpp"

#include <string>

#include "core/dynamics/finite_terms.hpp"
#include "core/dynamics/forward_dynamics.hpp"
#include "core/dynamics/mass_matrix_check.hpp"
#include "core/model/unit_slips.hpp"
#include "core/model/validation.hpp"
#include "core/simulation/integrators.hpp"
#include "core/simulation/robot_terms.hpp"

namespace ll {
namespace {

// Each number finite can still overflow in a term (a spring's rest at 1e300 gives
// E_pot = inf): the initial state's B, C, g, Q, q̈ and energies must be finite.
void checkFiniteAtInitialState(const Scene& scene, std::vector<Diagnostic>& out) {
    const int n = scene.robot.dof();
    if (scene.initial.q.size() != n || scene.initial.qd.size() != n) return;  // the field checks name it
    try {
        const RobotEvaluation e = evaluateRobot(scene, scene.initial.q, scene.initial.qd, 0.0);
        if (auto bad = nonFiniteTerm(e.terms, e.qdd, scene.initial.q, scene.initial.qd, MessageId::WhereInitialState)) out.push_back(*bad);
    } catch (const SingularMassMatrix&) {
        // B singular at the initial state but not at q = 0: simulate() reports it there.
    }
}

}  // namespace

std::vector<Diagnostic> validateRobot(const RobotModel& model) {
    std::vector<Diagnostic> out = validateRobotFields(model);
    if (!hasErrors(out) && model.dof() > 0) {
        const std::vector<Diagnostic> singular = checkMassMatrixRegular(model, Eigen::VectorXd::Zero(model.dof()), unitSlipWarnings(model));
        out.insert(out.end(), singular.begin(), singular.end());
    }
    return out;
}

std::vector<Diagnostic> validateScene(const Scene& scene) {
    std::vector<Diagnostic> out = validateSceneFields(scene);
    // As in validateRobot: B is checked once the robot's own fields are sound.
    if (!scene.lagrangian && scene.robot.dof() > 0 && !hasErrors(validateRobotFields(scene.robot))) {
        const std::vector<Diagnostic> singular =
            checkMassMatrixRegular(scene.robot, Eigen::VectorXd::Zero(scene.robot.dof()), unitSlipWarnings(scene.robot));
        out.insert(out.end(), singular.begin(), singular.end());
        if (!hasErrors(out)) checkFiniteAtInitialState(scene, out);
    }
    const std::string& integrator = scene.simulation.integrator;
    if (!findIntegrator(integrator))
        out.push_back({Severity::Error, "simulation.integrator", message(MessageId::UnknownIntegrator, integrator, integratorNames())});
    return out;
}

std::vector<Diagnostic> requireValidScene(const Scene& scene) {
    std::vector<Diagnostic> diagnostics = validateScene(scene);
    if (hasErrors(diagnostics)) throw InputError(diagnostics);
    std::vector<Diagnostic> warnings;
    for (const Diagnostic& d : diagnostics)
        if (d.severity == Severity::Warning) warnings.push_back(d);
    return warnings;
}

}  // namespace ll
