#include "core/dynamics/mass_matrix_check.hpp"

#include <random>
#include <string>

#include "core/dynamics/forward_dynamics.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/model/robot_data.hpp"

namespace ll {

std::vector<Diagnostic> checkMassMatrixRegular(const RobotModel& model, const Eigen::VectorXd& q0) {
    std::vector<Diagnostic> out;
    RobotData data(model);
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> angle(-3.0, 3.0);
    std::vector<int> singularCount(model.dof(), 0);
    const int trials = 4;
    for (int trial = 0; trial < trials; ++trial) {
        Eigen::VectorXd q = q0;
        if (trial > 0)
            for (int i = 0; i < q.size(); ++i) q[i] = angle(rng) * (model.joints[i].dh.type == JointType::Revolute ? 1.0 : 0.1);
        forwardKinematics(model, data, q);
        computeMassMatrix(model, data);
        const int joint = firstSingularJoint(data.B);
        if (joint >= 0) ++singularCount[joint];
    }
    for (int j = 0; j < model.dof(); ++j)
        if (singularCount[j] == trials)
            out.push_back({Severity::Error, jointField(j, ""),
                  "joint " + std::to_string(j + 1) +
                      " moves no mass or inertia that the joints before it do not already move, so the mass "
                      "matrix B(q) is singular; give link " + std::to_string(j + 1) +
                      " (or a link after it) mass off the joint axis or inertia about it"});
    return out;
}

}  // namespace ll
