#include "core/simulation/robot_ode.hpp"

#include <algorithm>
#include <cmath>

#include "core/math/cholesky.hpp"
#include "core/dynamics/forward_dynamics.hpp"
#include "core/dynamics/potential_gradient.hpp"
#include "core/dynamics/inverse_dynamics.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/model/argument_checks.hpp"
#include "core/model/friction_law.hpp"
#include "core/simulation/integrators.hpp"

namespace ll {

const char* toString(RhsTerm term) {
    switch (term) {
        case RhsTerm::MassMatrix: return "mass matrix";
        case RhsTerm::Coriolis: return "Coriolis";
        case RhsTerm::Gravity: return "gravity";
        case RhsTerm::Springs: return "springs";
        case RhsTerm::Viscous: return "viscous friction";
        case RhsTerm::Coulomb: return "Coulomb friction";
        case RhsTerm::Torques: return "torques";
        case RhsTerm::Control: return "control";
    }
    return "?";
}

namespace {
double signOf(double v) { return v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0); }
// A sliding Stick joint slower than this [rad/s or m/s] is at rest for the event logic
// (a located crossing ends within 1e-10 of zero).
constexpr double kRestSpeed = 1e-9;
}  // namespace

RobotOde::RobotOde(const RobotModel& model, const Effects& effects)
    : model_(model),
      effects_(effects),
      data_(model),
      q_(Eigen::VectorXd::Zero(model.dof())),
      qd_(Eigen::VectorXd::Zero(model.dof())),
      Q_(Eigen::VectorXd::Zero(model.dof())),
      rhs_(Eigen::VectorXd::Zero(model.dof())),
      qdd_(Eigen::VectorXd::Zero(model.dof())),
      cornerQ0_(Eigen::VectorXd::Zero(model.dof())),
      cornerQd0_(Eigen::VectorXd::Zero(model.dof())),
      cornerQ1_(Eigen::VectorXd::Zero(model.dof())),
      cornerQd1_(Eigen::VectorXd::Zero(model.dof())) {
    requireEffectsFit("RobotOde", effects, model.dof());
    // Conservative terms (into g) first, then the generalized forces (into Q).
    if (effects.gravity) terms_.push_back({RhsTerm::Gravity, &RobotOde::addGravity});
    if (!effects.springs.empty()) terms_.push_back({RhsTerm::Springs, &RobotOde::addSprings});
    if (!effects.viscous.empty()) terms_.push_back({RhsTerm::Viscous, &RobotOde::addViscous});
    bool tanhCoulomb = false;
    for (const CoulombFriction& f : effects.coulomb) {
        if (f.model == CoulombModel::Tanh) {
            tanhCoulomb = true;
            continue;
        }
        auto it = std::find_if(stick_.begin(), stick_.end(), [&](const StickJoint& s) { return s.joint == f.joint; });
        if (it == stick_.end()) it = stick_.insert(stick_.end(), StickJoint{f.joint});
        it->force += f.force;
    }
    if (tanhCoulomb) terms_.push_back({RhsTerm::Coulomb, &RobotOde::addTanhCoulomb});
    if (!stick_.empty()) terms_.push_back({RhsTerm::Coulomb, &RobotOde::addSlidingCoulomb});
    if (!effects.torques.empty()) terms_.push_back({RhsTerm::Torques, &RobotOde::addTorques});
    if (effects.control) {
        controller_.emplace(model, effects);
        terms_.push_back({RhsTerm::Control, &RobotOde::addControl});
    }
    hasGeneralizedForces_ = !effects.torques.empty() || effects.hasFriction() || effects.control.has_value();
}

std::vector<RhsTerm> RobotOde::terms() const {
    std::vector<RhsTerm> out = {RhsTerm::MassMatrix, RhsTerm::Coriolis};
    for (const Term& term : terms_)
        if (out.back() != term.kind) out.push_back(term.kind);
    return out;
}

std::vector<int> RobotOde::stuckJoints() const {
    std::vector<int> joints;
    for (const StickJoint& s : stick_)
        if (s.stuck) joints.push_back(s.joint);
    return joints;
}

OdeState RobotOde::initialState(const Eigen::VectorXd& q, const Eigen::VectorXd& qd) const {
    requireSize("RobotOde::initialState", "q", q.size(), data_.n);
    requireSize("RobotOde::initialState", "qd", qd.size(), data_.n);
    const int n = data_.n;
    OdeState x(2 * n + 1, 0.0);
    for (int i = 0; i < n; ++i) {
        x[i] = q[i];
        x[n + i] = qd[i];
    }
    return x;
}

void RobotOde::addGravity(double) { addGravityTorques(model_, data_, *effects_.gravity, data_.g); }
void RobotOde::addSprings(double) { addSpringTorques(effects_.springs, q_, data_.g); }
void RobotOde::addViscous(double) {
    for (const ViscousFriction& f : effects_.viscous) Q_[f.joint] += viscousFrictionForce(f.coefficient, qd_[f.joint]);
}
void RobotOde::addTanhCoulomb(double) {
    for (const CoulombFriction& f : effects_.coulomb)
        if (f.model == CoulombModel::Tanh) Q_[f.joint] += tanhCoulombForce(f.force, qd_[f.joint], f.smoothing);
}
// Sliding joints only; stuck ones get their holding force in solveAccelerations. The
// direction is the one of the step's start: a trial stage past q̇_i = 0 does not flip the
// force (that would chatter); the drivers locate the crossing (eventFraction) and
// afterStep decides there whether the joint sticks or turns round.
void RobotOde::addSlidingCoulomb(double) {
    for (const StickJoint& s : stick_) {
        if (s.stuck) continue;
        const double v = qd_[s.joint];
        Q_[s.joint] -= s.force * (s.sign != 0 ? s.sign : signOf(v));
    }
}

double RobotOde::eventFraction(const OdeState& x0, const OdeState& x1) const {
    const int n = data_.n;
    double theta = 1.0;
    for (const StickJoint& s : stick_) {
        if (s.stuck) continue;
        const double v0 = x0[n + s.joint], v1 = x1[n + s.joint];
        const double dir = s.sign != 0 ? s.sign : signOf(v0);
        if (!(v1 * dir < 0) || !(v0 * dir > kRestSpeed)) continue;          // (from rest: afterStep's business)
        if (std::abs(v1) <= 1e-10 * std::max(1.0, std::abs(v0))) continue;  // located closely enough
        theta = std::min(theta, v0 / (v0 - v1));
    }
    return std::clamp(theta, 1e-9, 1.0);
}
void RobotOde::addTorques(double t) {
    for (const JointTorque& torque : effects_.torques) Q_[torque.joint] += torque(t);
}

double RobotOde::cornerFraction(double t0, const OdeState& x0, double t1, const OdeState& x1) {
    if (!hasCorners()) return 1.0;
    const int n = data_.n;
    for (int i = 0; i < n; ++i) {
        cornerQ0_[i] = x0[i], cornerQd0_[i] = x0[n + i];
        cornerQ1_[i] = x1[i], cornerQd1_[i] = x1[n + i];
    }
    return controller_->cornerFraction(t0, cornerQ0_, cornerQd0_, t1, cornerQ1_, cornerQd1_);
}

// The controller's τ from the state (feedback): its own model, its own scratch data.
void RobotOde::addControl(double t) { Q_ += controller_->torque(t, q_, qd_); }

void RobotOde::evaluateForces(const OdeState& x, double t) {
    ++evaluations_;
    const int n = data_.n;
    for (int i = 0; i < n; ++i) {
        q_[i] = x[i];
        qd_[i] = x[n + i];
    }
    forwardKinematics(model_, data_, q_);
    computeMassMatrix(model_, data_);
    ++termCounts_[static_cast<int>(RhsTerm::MassMatrix)];
    static const Effects kNoEffects;
    data_.qdd.setZero();
    rhs_ = -rnea(model_, data_, kNoEffects, q_, qd_, data_.qdd);  // −C q̇
    ++termCounts_[static_cast<int>(RhsTerm::Coriolis)];
    data_.g.setZero();
    if (hasGeneralizedForces_) Q_.setZero();
    for (const Term& term : terms_) {
        (this->*term.add)(t);
        ++termCounts_[static_cast<int>(term.kind)];
    }
    rhs_ -= data_.g;
    if (hasGeneralizedForces_) rhs_ += Q_;
}

void RobotOde::solveAccelerations() {
    factorMassMatrix(data_);
    std::vector<int> held;
    for (size_t s = 0; s < stick_.size(); ++s)
        if (stick_[s].stuck) held.push_back(static_cast<int>(s));
    if (held.empty()) {
        qdd_ = rhs_;
        data_.B_llt.solveInPlace(qdd_);
        return;
    }
    // Held joints have q̈_i = 0; the rest solve B_FF q̈_F = rhs_F. The holding force of
    // joint i is f_i = (B q̈)_i − rhs_i; one that would exceed F_c is clamped to
    // ±F_c (kinetic friction against the motion that starts) and joins the free set.
    const int n = data_.n;
    for (;;) {
        std::vector<char> isHeld(n, 0);
        for (int s : held) isHeld[stick_[s].joint] = 1;
        std::vector<int> free;
        for (int i = 0; i < n; ++i)
            if (!isHeld[i]) free.push_back(i);
        const int m = static_cast<int>(free.size());
        Eigen::MatrixXd Bff(m, m);
        Eigen::VectorXd rf(m);
        for (int a = 0; a < m; ++a) {
            rf[a] = rhs_[free[a]];
            for (int b = 0; b < m; ++b) Bff(a, b) = data_.B(free[a], free[b]);
        }
        const Eigen::VectorXd af = m > 0 ? Cholesky(m).compute(Bff).solve(rf) : Eigen::VectorXd();
        qdd_.setZero();
        for (int a = 0; a < m; ++a) qdd_[free[a]] = af[a];
        int worst = -1;
        double worstRatio = 1.0, worstForce = 0.0;
        for (size_t h = 0; h < held.size(); ++h) {
            const int i = stick_[held[h]].joint;
            double f = -rhs_[i];
            for (int a = 0; a < m; ++a) f += data_.B(i, free[a]) * af[a];
            const double ratio = std::abs(f) / std::max(stick_[held[h]].force, 1e-300);
            if (ratio > worstRatio) {
                worst = static_cast<int>(h);
                worstRatio = ratio;
                worstForce = f;
            }
        }
        if (worst < 0) {
            for (int s : held) {  // book the holding forces (they do no work: q̇_i = 0)
                const int i = stick_[s].joint;
                double f = -rhs_[i];
                for (int a = 0; a < m; ++a) f += data_.B(i, free[a]) * af[a];
                Q_[i] += f;
            }
            return;
        }
        const int i = stick_[held[worst]].joint;
        const double clamp = stick_[held[worst]].force * signOf(worstForce);
        rhs_[i] += clamp;
        Q_[i] += clamp;
        held.erase(held.begin() + worst);
        if (held.empty()) {
            qdd_ = rhs_;
            data_.B_llt.solveInPlace(qdd_);
            return;
        }
    }
}

void RobotOde::operator()(const OdeState& x, OdeState& dxdt, double t) {
    try {
        evaluateForces(x, t);
        solveAccelerations();
    } catch (const SingularMassMatrix& e) {
        throw IntegrationError(t, x,
                               message(MessageId::AtTimeInSeconds, message(MessageId::MassMatrixSingularAtJoint, e.joint() + 1),
                                       std::to_string(t)));  // e.what() in words
    }
    const int n = data_.n;
    for (int i = 0; i < n; ++i) {
        dxdt[i] = qd_[i];
        dxdt[n + i] = qdd_[i];
    }
    dxdt[2 * n] = hasGeneralizedForces_ ? Q_.dot(qd_) : 0.0;
}

bool RobotOde::afterStep(double t, OdeState& x) {
    if (stick_.empty()) return false;
    const int n = data_.n;
    // A stuck joint that moved has broken free; a sliding joint whose velocity reached
    // zero or reversed during the step is a candidate to stick.
    std::vector<size_t> candidates;
    std::vector<std::pair<bool, double>> before;
    for (const StickJoint& j : stick_) before.emplace_back(j.stuck, j.sign);
    const auto modeChanged = [&] {
        for (size_t s = 0; s < stick_.size(); ++s)
            if (before[s] != std::make_pair(stick_[s].stuck, stick_[s].sign)) return true;
        return false;
    };
    for (size_t s = 0; s < stick_.size(); ++s) {
        StickJoint& j = stick_[s];
        const double v = x[n + j.joint];
        if (j.stuck && v != 0) {
            j.stuck = false;
            j.sign = signOf(v);
        } else if (!j.stuck && (std::abs(v) <= kRestSpeed || v * j.sign < 0)) {
            candidates.push_back(s);
        } else if (!j.stuck) {
            j.sign = signOf(v);
        }
    }
    for (size_t s : candidates) stick_[s].stuck = true;
    // Which stuck joints can friction hold at this state?
    try {
        evaluateForces(x, t);
        solveAccelerations();
    } catch (const SingularMassMatrix& e) {
        throw IntegrationError(t, x,
                               message(MessageId::AtTimeInSeconds, message(MessageId::MassMatrixSingularAtJoint, e.joint() + 1),
                                       std::to_string(t)));  // e.what() in words
    }
    for (StickJoint& j : stick_) {
        if (!j.stuck || qdd_[j.joint] == 0.0) continue;
        // The holding force would exceed F_c: it slides (or turns round) in the direction
        // it accelerates with F_c against it, which the clamped solve just gave.
        j.stuck = false;
        j.sign = signOf(qdd_[j.joint]);
    }
    // Stop the newly stuck joints with an inelastic impulse on the stuck joints only:
    // Δq̇ = B⁻¹ E_S λ with (B⁻¹)_SS λ = −q̇_S. It takes ½ q̇_Sᵀ ((B⁻¹)_SS)⁻¹ q̇_S of kinetic
    // energy (never adds any), booked as work of friction in W.
    std::vector<int> S;
    bool moving = false;
    for (const StickJoint& j : stick_)
        if (j.stuck) {
            S.push_back(j.joint);
            moving = moving || x[n + j.joint] != 0;
        }
    if (!moving) return modeChanged();
    const int k = static_cast<int>(S.size());
    Eigen::MatrixXd E = Eigen::MatrixXd::Zero(n, k);
    Eigen::VectorXd vS(k);
    for (int a = 0; a < k; ++a) {
        E(S[a], a) = 1.0;
        vS[a] = x[n + S[a]];
    }
    Eigen::MatrixXd M = E;  // becomes B⁻¹ E_S
    data_.B_llt.solveInPlace(M);
    Eigen::MatrixXd G(k, k);
    for (int a = 0; a < k; ++a) G.row(a) = M.row(S[a]);
    const Eigen::VectorXd lambda = -Cholesky(k).compute(G).solve(vS);
    const Eigen::VectorXd dqd = M * lambda;
    for (int i = 0; i < n; ++i) x[n + i] += dqd[i];
    for (int i : S) x[n + i] = 0.0;
    x[2 * n] += 0.5 * vS.dot(lambda);  // ΔE_kin = ½ q̇_Sᵀ λ ≤ 0
    for (size_t s : candidates)
        if (stick_[s].stuck) ++stickEvents_;
    return true;
}

}  // namespace ll
