#include "core/simulation/scene_validation.hpp"

#include <string>

#include "core/dynamics/mass_matrix_check.hpp"
#include "core/model/unit_slips.hpp"
#include "core/model/validation.hpp"
#include "core/simulation/integrators.hpp"

namespace ll {

std::vector<Diagnostic> validateRobot(const RobotModel& model) {
    std::vector<Diagnostic> out = validateRobotFields(model);
    if (!hasErrors(out) && model.dof() > 0) {
        const std::vector<Diagnostic> singular =
            checkMassMatrixRegular(model, Eigen::VectorXd::Zero(model.dof()), unitSlipWarnings(model));
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
    }
    const std::string& integrator = scene.simulation.integrator;
    if (!findIntegrator(integrator))
        out.push_back({Severity::Error, "simulation.integrator",
                       "unknown integrator '" + integrator + "' (known: " + integratorNames() + ")"});
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
