#include "core/simulation/robot_terms.hpp"

#include <cmath>

#include "core/dynamics/coriolis.hpp"
#include "core/dynamics/energy.hpp"
#include "core/dynamics/forward_dynamics.hpp"
#include "core/dynamics/potential_gradient.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/simulation/generalized_forces.hpp"

namespace ll {

RobotEvaluation evaluateRobot(const Scene& scene, const Eigen::VectorXd& q, const Eigen::VectorXd& qd, double t,
                              const std::optional<Eigen::VectorXd>& tau) {
    const RobotModel& robot = scene.robot;
    const int n = robot.dof();
    RobotEvaluation out;
    ModelTerms& m = out.terms;
    m.Q.resize(n);
    if (tau) {
        m.Q = *tau;
    } else {
        computeExternalTorques(scene.effects, t, m.Q);
        addControlTorques(robot, scene.effects, t, q, qd, m.Q);
    }
    addFrictionForces(scene.effects, qd, m.Q);

    RobotData data(robot);
    forwardKinematics(robot, data, q);
    computeMassMatrix(robot, data);
    computeCoriolisMatrix(robot, data, qd);
    computePotentialGradient(robot, data, scene.effects, q);
    m.B = data.B;
    m.C = data.C;
    m.g = data.g;
    m.Ekin = kineticEnergy(data, qd);
    m.Epot = potentialEnergy(robot, data, scene.effects, q);
    const bool finite =
        m.B.allFinite() && m.C.allFinite() && m.g.allFinite() && m.Q.allFinite() && std::isfinite(m.Ekin) && std::isfinite(m.Epot);
    if (finite) out.qdd = forwardDynamics(robot, data, scene.effects, q, qd, m.Q);
    return out;
}

}  // namespace ll
