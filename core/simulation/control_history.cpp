#include "core/simulation/control_history.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/dynamics/coriolis.hpp"
#include "core/dynamics/energy.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/kinematics/forward_kinematics.hpp"

namespace ll {

bool hasLyapunovFunction(const Control& control) {
    const bool pd = control.law == ControlLaw::Pd || control.law == ControlLaw::PdGravity;
    const ControlReference::Kind kind = control.reference.kind;
    return pd && (kind == ControlReference::Kind::Hold || kind == ControlReference::Kind::Step);
}

ControlHistory controlHistory(const SimulationInput& input, const Trajectory& trajectory, const TorqueHistory& torques) {
    const Scene& scene = input.scene;
    if (scene.lagrangian || !scene.effects.control) throw std::invalid_argument("controlHistory: the scene declares no controller");
    const int n = scene.dof();
    if (trajectory.n != n || torques.parts.size() != trajectory.size())
        throw std::invalid_argument("controlHistory: the trajectory has " + std::to_string(trajectory.n) + " coordinates and " +
                                    std::to_string(trajectory.size()) + " samples; the scene " + std::to_string(n) + ", the torques " +
                                    std::to_string(torques.parts.size()));
    const RobotModel& robot = scene.robot;
    Controller controller(robot, scene.effects);
    const Control& control = controller.control();
    ControlHistory history;
    TrackingSummary& s = history.summary;
    s.rmsError = s.maxError = s.maxTorque = s.saturatedFraction = Eigen::VectorXd::Zero(n);
    RobotData data(robot);
    const bool lyapunov = hasLyapunovFunction(control);
    if (lyapunov) history.lyapunov.emplace();
    double largestDissipation = 0.0, largestDeparture = 0.0;
    history.parts.reserve(trajectory.size());
    for (std::size_t k = 0; k < trajectory.size(); ++k) {
        const Eigen::VectorXd& q = trajectory.q[k];
        const Eigen::VectorXd& qd = trajectory.qd[k];
        ControlParts p = controller.parts(trajectory.t[k], q, qd);
        for (int i = 0; i < n; ++i) {
            s.rmsError[i] += p.error[i] * p.error[i];
            s.maxError[i] = std::max(s.maxError[i], std::abs(p.error[i]));
            s.maxTorque[i] = std::max(s.maxTorque[i], std::abs(p.tau[i]));
            if (control.drives(i) && i < control.torqueLimit.size() && std::abs(p.unsaturated[i]) > control.torqueLimit[i])
                s.saturatedFraction[i] += 1.0;
        }
        if (k > 0) {  // the actuators' work, trapezoidal
            const ControlParts& before = history.parts.back();
            const double dt = trajectory.t[k] - trajectory.t[k - 1];
            const double now = p.tau.cwiseProduct(qd).cwiseAbs().sum();
            const double then = before.tau.cwiseProduct(trajectory.qd[k - 1]).cwiseAbs().sum();
            s.energySpent += 0.5 * dt * (now + then);
        }
        if (lyapunov) {
            LyapunovHistory& l = *history.lyapunov;
            forwardKinematics(robot, data, q);
            computeMassMatrix(robot, data);
            computeMassMatrixDerivatives(robot, data);
            Eigen::MatrixXd Bdot = Eigen::MatrixXd::Zero(n, n);
            for (int j = 0; j < n; ++j) Bdot += data.dB_dq[static_cast<std::size_t>(j)] * qd[j];
            const Eigen::VectorXd& qdd = torques.parts[k].qdd;
            const Eigen::VectorXd Kpe = control.kp.cwiseProduct(p.error);
            double V = 0.5 * qd.dot(data.B * qd) + 0.5 * p.error.dot(Kpe);
            double Vdot = qd.dot(data.B * qdd) + 0.5 * qd.dot(Bdot * qd) - Kpe.dot(qd);
            if (control.law == ControlLaw::Pd) {
                const double here = trajectory.Epot[k];
                forwardKinematics(robot, data, p.qRef);
                V += here - potentialEnergy(robot, data, scene.effects, p.qRef);
                Vdot += torques.parts[k].potential.dot(qd);
            }
            const double dissipation = -qd.dot(control.kd.cwiseProduct(qd));
            l.V.push_back(V);
            l.Vdot.push_back(Vdot);
            l.dissipation.push_back(dissipation);
            largestDissipation = std::max(largestDissipation, -dissipation);
            largestDeparture = std::max(largestDeparture, std::abs(Vdot - dissipation));
        }
        history.parts.push_back(std::move(p));
    }
    if (!trajectory.t.empty()) {
        const double samples = static_cast<double>(trajectory.size());
        s.rmsError = (s.rmsError / samples).cwiseSqrt();
        s.saturatedFraction /= samples;
    }
    if (lyapunov) history.lyapunov->largestDeparture = largestDissipation > 0 ? largestDeparture / largestDissipation : 0.0;
    return history;
}

}  // namespace ll
