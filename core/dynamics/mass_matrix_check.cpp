#include "core/dynamics/mass_matrix_check.hpp"

#include <random>
#include <sstream>
#include <string>

#include "core/dynamics/mass_matrix.hpp"
#include "core/dynamics/mass_matrix_conditioning.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/model/robot_data.hpp"

namespace ll {
namespace {

std::string fmt(double v) { return formatValue(v); }

// What to do about a joint that moves (almost) nothing: give its links inertia, or
// its motor's.
std::string armatureAdvice(int j) {
    return "or add the motor's inertia as armature (\"armature\": Jm*G^2, or \"motor\": {\"inertia\": Jm, "
           "\"gear_ratio\": G} on joint " + std::to_string(j + 1) +
           "): published tables often leave light distal links without inertia, but the motor's rotor still "
           "turns with the joint";
}

// The error for a B(q) that cannot be factored: one short line saying which kind it is
// (core/dynamics/mass_matrix_conditioning.hpp), and a hint with the likely cause and the
// fix. When the links from joint j on carry no mass and no inertia at all, that one
// value is named: the link's mass.
Diagnostic singularMassMatrixError(const RobotModel& model, const MassMatrixDefect& defect, const std::vector<Diagnostic>& unitSlips) {
    const int j = defect.joint;
    const std::string joint = std::to_string(j + 1);
    if (defect.kind == MassMatrixDefect::Kind::MovesNothing) {
        bool nothingAfter = true;
        for (int i = j; i < model.dof(); ++i)
            nothingAfter = nothingAfter && model.joints[i].link.mass == 0.0 && model.joints[i].link.inertia.isZero();
        const std::string hint = "B(q) has no inertia along joint " + joint + "; give link " + joint +
                                 " (or a link after it) mass off the joint axis or inertia about it, " + armatureAdvice(j);
        if (nothingAfter)
            return {Severity::Error, jointField(j, "mass"),
                    "joint " + joint + " moves no mass or inertia: link " + joint + " and the links after it have none, so the mass matrix B(q) is singular",
                    hint};
        return {Severity::Error, jointField(j, ""),
                "joint " + joint + " moves no mass or inertia of its own, so the mass matrix B(q) is singular", hint};
    }
    const std::string message = "the mass matrix B(q) is too ill-conditioned to use (condition number " + fmt(defect.condition) +
                                ") at joint " + joint;
    std::string hint = "joint " + joint + " moves inertia of its own (b" + joint + joint + " = " + fmt(defect.diagonal) +
                       "), but beside the largest diagonal entry (" + fmt(defect.largest) +
                       ") double precision loses it; likely cause: ";
    if (unitSlips.empty()) {
        hint += "light distal links beside heavy ones: check their masses and inertias, " + armatureAdvice(j);
        return {Severity::Error, jointField(j, ""), message, hint};
    }
    hint += "a unit slip, " + unitSlips.front().where() + ": " + unitSlips.front().message;
    if (unitSlips.size() > 1) hint += " (and " + std::to_string(unitSlips.size() - 1) + " more unit warnings)";
    return {Severity::Error, unitSlips.front().field, message, hint};
}

// B(q) must be positive definite wherever the robot may go. A structurally massless
// joint shows at (almost) every configuration, so test the start and a few random ones.
}  // namespace

std::vector<Diagnostic> checkMassMatrixRegular(const RobotModel& model, const Eigen::VectorXd& q0,
                                               const std::vector<Diagnostic>& unitSlips) {
    std::vector<Diagnostic> out;
    RobotData data(model);
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> angle(-3.0, 3.0);
    std::vector<int> singularCount(model.dof(), 0);
    std::vector<MassMatrixDefect> defects(model.dof());
    const int trials = 4;
    for (int trial = 0; trial < trials; ++trial) {
        Eigen::VectorXd q = q0;
        if (trial > 0)
            for (int i = 0; i < q.size(); ++i) q[i] = angle(rng) * (model.joints[i].dh.type == JointType::Revolute ? 1.0 : 0.1);
        forwardKinematics(model, data, q);
        computeMassMatrix(model, data);
        const MassMatrixDefect defect = diagnoseMassMatrix(data);
        if (defect.joint >= 0) {
            ++singularCount[defect.joint];
            defects[defect.joint] = defect;
        }
    }
    for (int j = 0; j < model.dof(); ++j)
        if (singularCount[j] == trials)
            out.push_back(singularMassMatrixError(model, defects[j], unitSlips));
    return out;
}


}  // namespace ll
