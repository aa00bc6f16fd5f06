#include "core/simulation/controller.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/dynamics/inverse_dynamics.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/dynamics/potential_gradient.hpp"
#include "core/kinematics/forward_kinematics.hpp"

namespace ll {

namespace {
// Two times this close are one for a corner: a step starting or ending this near one is at
// it (a step this short would be taken for a collapsed one: integration_drivers.hpp).
double nearTime(double t) { return 1e-10 * std::max(1.0, std::abs(t)); }

// The first of `corners` (increasing) after t and not at it.
std::vector<double>::const_iterator cornerAfter(const std::vector<double>& corners, double t) {
    return std::upper_bound(corners.begin(), corners.end(), t + nearTime(t));
}
}  // namespace

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
      zero_(Eigen::VectorXd::Zero(plant.dof())),
      demandStart_(Eigen::VectorXd::Zero(plant.dof())) {
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
    // Corners closer than nearTime are one (two joints' phases ending together, apart by a rounding).
    for (double c : control_.reference.corners())
        if (corners_.empty() || c - corners_.back() > nearTime(c)) corners_.push_back(c);
}

void Controller::reference(double t) {
    // Inside the piece by nearTime: a corner's own time and the reference's switch (t − t0
    // against a phase's length) may differ by a rounding, which must not put a stage of a
    // step ending on the corner past the jump.
    double at = t;
    if (std::isfinite(segmentStart_)) at = std::max(at, segmentStart_ + nearTime(segmentStart_));
    if (std::isfinite(segmentEnd_)) at = std::min(at, segmentEnd_ - nearTime(segmentEnd_));
    control_.reference.evaluate(at, qRef_, qdRef_, qddRef_);
}

bool Controller::enterSegment(double t) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const auto next = cornerAfter(corners_, t);
    const double end = next == corners_.end() ? inf : *next, start = next == corners_.begin() ? -inf : *(next - 1);
    const bool changed = end != segmentEnd_ || start != segmentStart_;
    segmentStart_ = start, segmentEnd_ = end;
    return changed;
}

void Controller::saturate(Eigen::VectorXd& tau) const {
    for (Eigen::Index i = 0; i < tau.size(); ++i) {
        if (!control_.drives(static_cast<int>(i))) tau[i] = 0.0;
        else if (i < control_.torqueLimit.size()) tau[i] = std::clamp(tau[i], -control_.torqueLimit[i], control_.torqueLimit[i]);
    }
}

const Eigen::VectorXd& Controller::torque(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
    demand(t, q, qd);
    saturate(tau_);
    return tau_;
}

double Controller::nextCorner(double t) const {
    const auto next = cornerAfter(corners_, t);
    return next == corners_.end() ? std::numeric_limits<double>::infinity() : *next;
}

double Controller::cornerFraction(double t0, const Eigen::VectorXd& q0, const Eigen::VectorXd& qd0, double t1, const Eigen::VectorXd& q1,
                                  const Eigen::VectorXd& qd1) {
    const double h = t1 - t0;
    if (!(h > 0)) return 1.0;
    double theta = 1.0;
    // The fraction of a corner at t0 + f h, unless it is at either end already.
    const auto consider = [&](double f) {
        if (f * h > nearTime(t0) && (1 - f) * h > nearTime(t1)) theta = std::min(theta, f);
    };
    if (control_.torqueLimit.size() > 0) {
        // s_i = |τ_i| − limit_i changes sign where joint i starts or stops saturating: a
        // secant estimate, refined by the drivers' retries. (A torque swinging from beyond
        // +limit to beyond −limit within one step is not seen: the step would have to be
        // far longer than the law's time scale.)
        demand(t0, q0, qd0);
        demandStart_ = tau_;
        demand(t1, q1, qd1);
        for (Eigen::Index i = 0; i < control_.torqueLimit.size() && i < tau_.size(); ++i) {
            if (!control_.drives(static_cast<int>(i))) continue;
            const double limit = control_.torqueLimit[i];
            const double a = std::abs(demandStart_[i]) - limit, b = std::abs(tau_[i]) - limit;
            if ((a < 0 && b > 0) || (a > 0 && b < 0)) consider(a / (a - b));
        }
    }
    return std::clamp(theta, 1e-9, 1.0);
}

void Controller::demand(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
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
