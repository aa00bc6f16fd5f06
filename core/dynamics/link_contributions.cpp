#include "core/dynamics/link_contributions.hpp"

#include "core/dynamics/coriolis.hpp"
#include "core/dynamics/energy.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/dynamics/potential_gradient.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/model/argument_checks.hpp"

namespace ll {

LinkContributions::LinkContributions(const RobotModel& robot, const Effects& effects) {
    gravity_.gravity = effects.gravity;
    const int n = robot.dof();
    for (int i = 0; i < n; ++i) {
        RobotModel alone = robot;
        for (int k = 0; k < n; ++k) {
            alone.joints[k].motor = JointMotor{};
            if (k != i) alone.joints[k].link = LinkInertia{};
        }
        models_.push_back(std::move(alone));
    }
    for (const RobotModel& m : models_) data_.emplace_back(m);
    Ekin_.assign(n, 0.0);
    Epot_.assign(n, 0.0);
}

void LinkContributions::evaluate(const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
    const int n = links();
    requireSize("LinkContributions::evaluate", "q", q.size(), n, "the robot", "joints");
    requireSize("LinkContributions::evaluate", "qd", qd.size(), n, "the robot", "joints");
    for (int i = 0; i < n; ++i) {
        RobotData& d = data_[i];
        forwardKinematics(models_[i], d, q);
        computeMassMatrix(models_[i], d);
        computeCoriolisMatrix(models_[i], d, qd);
        computePotentialGradient(models_[i], d, gravity_, q);
        Ekin_[i] = kineticEnergy(d, qd);
        Epot_[i] = potentialEnergy(models_[i], d, gravity_, q);
    }
}

}  // namespace ll
