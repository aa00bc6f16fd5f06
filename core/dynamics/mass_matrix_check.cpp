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

// The error for a B(q) that cannot be factored: one short line saying which kind it is
// (core/dynamics/mass_matrix_conditioning.hpp), and a hint with the likely cause and the
// fix (among them, adding the motor's inertia as armature). When the links from joint j
// on carry no mass and no inertia at all, that one value is named: the link's mass.
Diagnostic singularMassMatrixError(const RobotModel& model, const MassMatrixDefect& defect, const std::vector<Diagnostic>& unitSlips) {
    using enum MessageId;
    const int j = defect.joint;
    const int joint = j + 1;
    const Message armatureAdvice = message(ArmatureAdvice, joint);
    if (defect.kind == MassMatrixDefect::Kind::MovesNothing) {
        bool nothingAfter = true;
        for (int i = j; i < model.dof(); ++i)
            nothingAfter = nothingAfter && model.joints[i].link.mass == 0.0 && model.joints[i].link.inertia.isZero();
        const Message hint = message(NoInertiaAlongJoint, joint, armatureAdvice);
        if (nothingAfter) return {Severity::Error, jointField(j, "mass"), message(JointAndLaterMoveNothing, joint), hint};
        return {Severity::Error, jointField(j, ""), message(JointMovesNothingOfItsOwn, joint), hint};
    }
    const Message error = message(MassMatrixIllConditioned, defect.condition, joint);
    const auto hint = [&](Message cause) { return message(IllConditionedHint, joint, defect.diagonal, defect.largest, std::move(cause)); };
    if (unitSlips.empty()) return {Severity::Error, jointField(j, ""), error, hint(message(LikelyLightLinks, armatureAdvice))};
    const Diagnostic& slip = unitSlips.front();
    const Message cause = unitSlips.size() > 1
                              ? message(LikelyUnitSlips, slip.place(), slip.message, static_cast<int>(unitSlips.size() - 1))
                              : message(LikelyUnitSlip, slip.place(), slip.message);
    return {Severity::Error, slip.field, error, hint(cause)};
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
        if (singularCount[j] == trials) out.push_back(singularMassMatrixError(model, defects[j], unitSlips));
    return out;
}

}  // namespace ll
