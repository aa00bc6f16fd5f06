#include "core/model/control.hpp"

#include <algorithm>
#include <cmath>

namespace ll {
namespace {

// The phases of a rest-to-rest move of |distance| d under |v| ≤ vmax and |a| ≤ amax:
// `ramp` seconds speeding up to `top`, `cruise` seconds at it, `ramp` seconds slowing
// down (a triangle, cruise = 0, when vmax is not reached). False for no move.
bool trapezoidPhases(double d, double vmax, double amax, double& ramp, double& cruise, double& top) {
    if (d == 0 || vmax <= 0 || amax <= 0) return false;
    ramp = vmax / amax;                                      // time to full speed
    if (amax * ramp * ramp > d) ramp = std::sqrt(d / amax);  // a triangle: top speed never reached
    top = amax * ramp, cruise = (d - amax * ramp * ramp) / top;
    return true;
}

// A rest-to-rest move of `distance` under |v| ≤ vmax and |a| ≤ amax, `s` seconds in:
// position, velocity and acceleration.
void trapezoid(double distance, double vmax, double amax, double s, double& x, double& v, double& a) {
    const double sign = distance < 0 ? -1.0 : 1.0, d = std::abs(distance);
    double ramp, cruise, top;
    if (!trapezoidPhases(d, vmax, amax, ramp, cruise, top)) {
        x = s > 0 ? distance : 0.0, v = a = 0.0;
        return;
    }
    const double total = 2 * ramp + cruise;
    if (s <= 0) {
        x = v = a = 0.0;
    } else if (s < ramp) {
        x = 0.5 * amax * s * s, v = amax * s, a = amax;
    } else if (s < ramp + cruise) {
        x = 0.5 * amax * ramp * ramp + top * (s - ramp), v = top, a = 0.0;
    } else if (s < total) {
        const double left = total - s;
        x = d - 0.5 * amax * left * left, v = amax * left, a = -amax;
    } else {
        x = d, v = a = 0.0;
    }
    x *= sign, v *= sign, a *= sign;
}

// The quintic s(τ) = 10τ³ − 15τ⁴ + 6τ⁵ from q0 to q1 over [t0, t0 + duration]: rest to
// rest with no jump in acceleration; held at q0 before and q1 after.
void quintic(const Eigen::VectorXd& q0, const Eigen::VectorXd& q1, double t0, double duration, double t, Eigen::VectorXd& q,
             Eigen::VectorXd& qd, Eigen::VectorXd& qdd) {
    const double tau = std::clamp((t - t0) / duration, 0.0, 1.0);
    const bool moving = t > t0 && t < t0 + duration;
    const double s = tau * tau * tau * (10 - 15 * tau + 6 * tau * tau);
    const double ds = moving ? 30 * tau * tau * (1 - tau) * (1 - tau) / duration : 0.0;
    const double dds = moving ? 60 * tau * (1 - tau) * (1 - 2 * tau) / (duration * duration) : 0.0;
    for (Eigen::Index i = 0; i < q.size(); ++i) {
        const double d = q1[i] - q0[i];
        q[i] = q0[i] + d * s, qd[i] = d * ds, qdd[i] = d * dds;
    }
}

}  // namespace

void ControlReference::evaluate(double t, Eigen::VectorXd& q, Eigen::VectorXd& qd, Eigen::VectorXd& qdd) const {
    const Eigen::Index n = q.size();
    switch (kind) {
        case Kind::Hold: q = q0, qd.setZero(), qdd.setZero(); return;
        case Kind::Step: q = t < t0 ? q0 : q1, qd.setZero(), qdd.setZero(); return;
        case Kind::Quintic: quintic(q0, q1, t0, duration, t, q, qd, qdd); return;
        case Kind::Waypoints: {
            // the segment [times[k], times[k+1]] holding t (the first before, the last after)
            std::size_t k = 0;
            while (k + 2 < times.size() && t >= times[k + 1]) ++k;
            quintic(points[k], points[k + 1], times[k], times[k + 1] - times[k], t, q, qd, qdd);
            return;
        }
        case Kind::Trapezoidal:
            for (Eigen::Index i = 0; i < n; ++i) {
                double x, v, a;
                trapezoid(q1[i] - q0[i], velocity[i], acceleration[i], t - t0, x, v, a);
                q[i] = q0[i] + x, qd[i] = v, qdd[i] = a;
            }
            return;
        case Kind::Sine: {
            const double w = 2 * M_PI * frequency, arg = w * t + phase;
            for (Eigen::Index i = 0; i < n; ++i) {
                q[i] = q0[i] + amplitude[i] * std::sin(arg);
                qd[i] = amplitude[i] * w * std::cos(arg);
                qdd[i] = -amplitude[i] * w * w * std::sin(arg);
            }
            return;
        }
    }
}

std::vector<double> ControlReference::corners() const {
    std::vector<double> at;
    switch (kind) {
        case Kind::Hold:
        case Kind::Sine: break;
        case Kind::Step: at = {t0}; break;
        case Kind::Quintic: at = {t0, t0 + duration}; break;
        case Kind::Waypoints: at = times; break;
        case Kind::Trapezoidal:
            for (Eigen::Index i = 0; i < q0.size() && i < q1.size() && i < velocity.size() && i < acceleration.size(); ++i) {
                double ramp, cruise, top;
                if (!trapezoidPhases(std::abs(q1[i] - q0[i]), velocity[i], acceleration[i], ramp, cruise, top)) continue;
                at.insert(at.end(), {t0, t0 + ramp, t0 + ramp + cruise, t0 + 2 * ramp + cruise});
            }
            break;
    }
    std::sort(at.begin(), at.end());
    at.erase(std::unique(at.begin(), at.end()), at.end());
    return at;
}

bool Control::drives(int joint) const { return joints.empty() || std::find(joints.begin(), joints.end(), joint) != joints.end(); }

Message lawImpossible(const Control& control, int n) {
    const int actuated = control.joints.empty() ? n : static_cast<int>(control.joints.size());
    if (control.law == ControlLaw::ComputedTorque && actuated < n) return message(MessageId::ComputedTorqueUnderactuated, actuated, n);
    return {};
}

const char* toString(ControlLaw law) {
    switch (law) {
        case ControlLaw::Pd: return "pd";
        case ControlLaw::PdGravity: return "pd_gravity";
        case ControlLaw::ComputedTorque: return "computed_torque";
        case ControlLaw::Feedforward: return "feedforward";
    }
    return "";
}

const char* toString(ControlReference::Kind kind) {
    switch (kind) {
        case ControlReference::Kind::Hold: return "hold";
        case ControlReference::Kind::Step: return "step";
        case ControlReference::Kind::Quintic: return "quintic";
        case ControlReference::Kind::Trapezoidal: return "trapezoidal";
        case ControlReference::Kind::Sine: return "sine";
        case ControlReference::Kind::Waypoints: return "waypoints";
    }
    return "";
}

}  // namespace ll
