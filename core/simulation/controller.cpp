#include "core/simulation/controller.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/dynamics/inverse_dynamics.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/dynamics/potential_gradient.hpp"
#include "core/kinematics/forward_kinematics.hpp"

namespace ll {

RobotModel controllerModel(const RobotModel& plant, const ControllerModel& changes) {
    RobotModel model = plant;
    for (const ControllerLink& own : changes.links)
        if (own.joint >= 0 && own.joint < static_cast<int>(model.joints.size())) model.joints[static_cast<std::size_t>(own.joint)].link = own.link;
    for (std::size_t i = 0; i < model.joints.size() && static_cast<Eigen::Index>(i) < changes.scale.size(); ++i) {
        const double s = changes.scale[static_cast<Eigen::Index>(i)];
        model.joints[i].link.mass *= s;
        model.joints[i].link.inertia *= s;
    }
    if (changes.payloadMass > 0 && !model.joints.empty()) {
        LinkInertia& link = model.joints.back().link;
        const double m = link.mass + changes.payloadMass;
        const Eigen::Vector3d com = (link.mass * link.com + changes.payloadMass * changes.payloadCom) / m;
        // Each inertia moved to the common COM (parallel-axis theorem, I + m (|r|² E − r rᵀ)).
        const auto moved = [&](const Eigen::Matrix3d& I, double mass, const Eigen::Vector3d& at) {
            const Eigen::Vector3d r = at - com;
            return Eigen::Matrix3d(I + mass * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose()));
        };
        link.inertia = moved(link.inertia, link.mass, link.com) + moved(changes.payloadInertia, changes.payloadMass, changes.payloadCom);
        link.mass = m;
        link.com = com;
    }
    return model;
}

Controller::Controller(const RobotModel& plant, const Effects& plantEffects)
    : control_(plantEffects.control.value()),
      model_(controllerModel(plant, control_.model)),
      data_(model_),
      qRef_(Eigen::VectorXd::Zero(plant.dof())),
      qdRef_(Eigen::VectorXd::Zero(plant.dof())),
      qddRef_(Eigen::VectorXd::Zero(plant.dof())),
      a_(Eigen::VectorXd::Zero(plant.dof())),
      tau_(Eigen::VectorXd::Zero(plant.dof())),
      zero_(Eigen::VectorXd::Zero(plant.dof())) {
    const Eigen::Index n = plant.dof();
    if (control_.wn.size() == n) {  // the gains from a natural frequency and damping ratio (core/model/control.hpp)
        const Eigen::VectorXd zeta = control_.zeta.size() == n ? control_.zeta : Eigen::VectorXd::Ones(n);
        Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
        if (control_.law != ControlLaw::ComputedTorque) {
            reference(0.0);
            forwardKinematics(model_, data_, qRef_);
            computeMassMatrix(model_, data_);
            b = data_.B.diagonal();
        }
        control_.kp = b.cwiseProduct(control_.wn.cwiseProduct(control_.wn));
        control_.kd = 2 * b.cwiseProduct(zeta.cwiseProduct(control_.wn));
    }
    if (control_.kp.size() != n || control_.kd.size() != n) throw std::invalid_argument("Controller: kp and kd need one gain per joint");
    conservative_.gravity = plantEffects.gravity;
    conservative_.springs = plantEffects.springs;
}

void Controller::reference(double t) { control_.reference.evaluate(t, qRef_, qdRef_, qddRef_); }

void Controller::saturate(Eigen::VectorXd& tau) const {
    for (Eigen::Index i = 0; i < tau.size(); ++i) {
        if (!control_.drives(static_cast<int>(i))) tau[i] = 0.0;
        else if (i < control_.torqueLimit.size()) tau[i] = std::clamp(tau[i], -control_.torqueLimit[i], control_.torqueLimit[i]);
    }
}

const Eigen::VectorXd& Controller::torque(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
    reference(t);
    const Eigen::Index n = q.size();
    switch (control_.law) {
        case ControlLaw::Pd:
        case ControlLaw::PdGravity:
            for (Eigen::Index i = 0; i < n; ++i) tau_[i] = control_.kp[i] * (qRef_[i] - q[i]) + control_.kd[i] * (qdRef_[i] - qd[i]);
            if (control_.law == ControlLaw::PdGravity && (conservative_.gravity || !conservative_.springs.empty())) {
                forwardKinematics(model_, data_, q);
                data_.g.setZero();
                if (conservative_.gravity) addGravityTorques(model_, data_, *conservative_.gravity, data_.g);
                addSpringTorques(conservative_.springs, q, data_.g);
                tau_ += data_.g;
            }
            break;
        case ControlLaw::ComputedTorque:
            // τ = B̂ (q̈_d + K_p e + K_d ė) + Ĉ q̇ + ĝ: inverse dynamics of the commanded acceleration.
            for (Eigen::Index i = 0; i < n; ++i)
                a_[i] = qddRef_[i] + control_.kp[i] * (qRef_[i] - q[i]) + control_.kd[i] * (qdRef_[i] - qd[i]);
            forwardKinematics(model_, data_, q);
            tau_ = rnea(model_, data_, conservative_, q, qd, a_);
            break;
        case ControlLaw::Feedforward:
            forwardKinematics(model_, data_, qRef_);
            tau_ = rnea(model_, data_, conservative_, qRef_, qdRef_, qddRef_);
            for (Eigen::Index i = 0; i < n; ++i) tau_[i] += control_.kp[i] * (qRef_[i] - q[i]) + control_.kd[i] * (qdRef_[i] - qd[i]);
            break;
    }
    saturate(tau_);
    return tau_;
}

ControlParts Controller::parts(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
    const Eigen::Index n = q.size();
    ControlParts p;
    reference(t);
    p.qRef = qRef_, p.qdRef = qdRef_, p.qddRef = qddRef_;
    p.error = qRef_ - q;
    p.errorRate = qdRef_ - qd;
    p.proportional = control_.kp.cwiseProduct(p.error);
    p.derivative = control_.kd.cwiseProduct(p.errorRate);
    p.inertial = p.coriolis = p.gravity = Eigen::VectorXd::Zero(n);
    static const Effects kNone;
    const bool model = control_.law != ControlLaw::Pd;
    if (model) {
        // B̂, Ĉ q̇ and ĝ where the law takes them: at the reference for feedforward, else at the state.
        const bool atReference = control_.law == ControlLaw::Feedforward;
        const Eigen::VectorXd& qm = atReference ? qRef_ : q;
        const Eigen::VectorXd& qdm = atReference ? qdRef_ : qd;
        forwardKinematics(model_, data_, qm);
        data_.g.setZero();
        if (conservative_.gravity) addGravityTorques(model_, data_, *conservative_.gravity, data_.g);
        addSpringTorques(conservative_.springs, qm, data_.g);
        p.gravity = data_.g;
        if (control_.law != ControlLaw::PdGravity) {
            computeMassMatrix(model_, data_);
            const Eigen::MatrixXd B = data_.B;
            p.coriolis = rnea(model_, data_, kNone, qm, qdm, zero_);
            p.inertial = B * qddRef_;
            if (control_.law == ControlLaw::ComputedTorque) {
                p.proportional = B * p.proportional;
                p.derivative = B * p.derivative;
            }
        }
    }
    p.unsaturated = p.inertial + p.coriolis + p.gravity + p.proportional + p.derivative;
    p.tau = p.unsaturated;
    saturate(p.tau);
    return p;
}

}  // namespace ll
