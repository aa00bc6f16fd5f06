#pragma once
// Internal to core/simulation: the drivers behind integrate() (guards, stiffness
// monitor, event handling, output times), shared by integrators.cpp and rosenbrock4.cpp.
// rosenbrock4.cpp is compiled as C++17 (Boost 1.74's uBLAS, which Odeint's rosenbrock4
// needs, uses std::allocator::construct, removed in C++20), so this header is C++17.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <type_traits>
#include <utility>

#include <Eigen/Eigenvalues>
#include <boost/numeric/odeint.hpp>

#include "core/simulation/integrators.hpp"

namespace ll::detail {
namespace odeint = boost::numeric::odeint;

using State = OdeState;

template <class V>
inline std::string describeState(const V& x) {
    std::ostringstream s;
    s.precision(6);
    s << "[";
    for (size_t i = 0; i < x.size(); ++i) s << (i ? ", " : "") << x[i];
    s << "]";
    return s.str();
}

template <class V>
inline bool allFinite(const V& x) {
    return std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); });
}

template <class V>
State toState(const V& x) {
    return State(x.begin(), x.end());
}

inline std::string fmt(double v) {
    std::ostringstream s;
    s.precision(3);
    s << v;
    return s.str();
}

// Stiffness of an explicit adaptive method, judged every `window` accepted steps: the
// run is stiff for it when (a) at the mean step size of the window the whole run would
// take more than `minSteps` steps, (b) that step sits at the stability limit of the
// fastest mode of the Jacobian (h |λ_max| >= 1; a step resolving that mode for accuracy
// is several times shorter), and (c) that mode is at least `ratio` times faster than the
// slowest non-zero mode, which is what the step could follow otherwise.
class StiffnessMonitor {
public:
    StiffnessMonitor(OdeSystem& system, const IntegrationSettings& settings, double t0, double t1, IntegrationCounts& counts)
        : system_(system), settings_(settings), t0_(t0), t1_(t1), counts_(counts) {
        const IntegratorInfo* info = findIntegrator(settings.integrator);
        enabled_ = settings.detectStiffness && info->adaptive && settings.integrator != "rosenbrock4";
    }

    template <class V>
    void onStep(double t, double h, const V& x) {
        if (!enabled_) return;
        ++steps_;
        span_ += h;
        if (steps_ < kWindow) return;
        const double hMean = span_ / steps_;
        steps_ = 0;
        span_ = 0;
        const double projected = (t1_ - t0_) / hMean;
        if (projected < kMinSteps) return;
        const State state = toState(x);
        Eigen::MatrixXd J;
        numericJacobian(system_, state, t, J);
        ++counts_.jacobians;
        const Eigen::VectorXd modulus = Eigen::EigenSolver<Eigen::MatrixXd>(J, false).eigenvalues().cwiseAbs();
        const double fastest = modulus.maxCoeff();
        double slowest = fastest;
        for (double m : modulus)
            if (m > 1e-9 * fastest) slowest = std::min(slowest, m);
        if (!(hMean * fastest >= 1.0 && fastest >= kRatio * slowest)) return;
        throw IntegrationError(t, state,
                               message(MessageId::SceneStiffFor, settings_.integrator, fmt(t), fmt(hMean), fmt(fastest),
                                       fmt(2 * 3.14159265358979323846 / fastest), fmt(fastest / slowest), fmt(slowest), fmt(projected)));
    }

private:
    static constexpr long kWindow = 2000;
    static constexpr double kMinSteps = 5e4, kRatio = 100.0;
    OdeSystem& system_;
    const IntegrationSettings& settings_;
    double t0_, t1_;
    IntegrationCounts& counts_;
    bool enabled_ = false;
    long steps_ = 0;
    double span_ = 0.0;
};

// Shared guards for every driver: finite state, a step size that has not collapsed,
// a bounded number of steps, and stiffness of explicit adaptive methods.
struct Guard {
    const IntegrationSettings& settings;
    IntegrationCounts& counts;
    StiffnessMonitor& stiffness;

    template <class V>
    void afterStep(double t, double dt, const V& x) const {
        if (!allFinite(x))
            throw IntegrationError(t, toState(x),
                                   message(MessageId::StateNotFinite, std::to_string(t), describeState(x), settings.integrator,
                                           Message(findIntegrator(settings.integrator)->adaptive ? MessageId::TightenTolerances
                                                                                                 : MessageId::StepTooLargeForScene)));
        if (dt < 1e-12 * std::max(1.0, std::abs(t)))
            throw IntegrationError(t, toState(x),
                                   message(MessageId::StepSizeCollapsed, std::to_string(dt), std::to_string(t), describeState(x)));
        if (++counts.steps > settings.maxSteps)
            throw IntegrationError(t, toState(x), message(MessageId::GaveUpAfterSteps, settings.maxSteps, std::to_string(t)));
        stiffness.onStep(t, dt, x);
    }
};

inline bool ahead(double target, double t) { return target - t > 1e-12 * std::max(1.0, std::abs(target)); }

// Steppers with internal history (Bulirsch–Stoer) must forget it after an event.
template <class Stepper, class = void>
struct HasReset : std::false_type {};
template <class Stepper>
struct HasReset<Stepper, std::void_t<decltype(std::declval<Stepper&>().reset())>> : std::true_type {};

template <class Stepper>
void resetAfterEvent(Stepper& stepper) {
    if constexpr (HasReset<Stepper>::value) stepper.reset();
}

// Gives x to the system's events; true when it changed x.
inline bool event(OdeSystem& system, double t, State& x) { return system.hasEvents() && system.afterStep(t, x); }

// The adaptive drivers stop at events and corners alike (OdeSystem).
inline bool locates(OdeSystem& system) { return system.hasEvents() || system.hasCorners(); }
// Where in the step from (t0, x0) to (t1, x1) the first event or corner lies: a fraction (0, 1), or 1.
inline double firstEvent(OdeSystem& system, double t0, const State& x0, double t1, const State& x1) {
    double theta = system.hasEvents() ? system.eventFraction(x0, x1) : 1.0;
    if (system.hasCorners()) theta = std::min(theta, system.cornerFraction(t0, x0, t1, x1));
    return theta;
}

// Event location for a dense-output stepper: the time in (t0, t1] just after the first
// event or corner of the last step (secant iterations on the dense output), or t1.
template <class DenseStepper, class V>
double locateEvent(DenseStepper& stepper, OdeSystem& system, const State& x0, double t0, V& out, State& xs) {
    const double t1 = stepper.current_time();
    std::copy(stepper.current_state().begin(), stepper.current_state().end(), xs.begin());
    double theta = firstEvent(system, t0, x0, t1, xs);
    if (theta >= 1.0) return t1;
    double lo = t0, hi = t1;  // the crossing lies in (lo, hi]
    State xlo = x0, xhi = xs;
    for (int iteration = 0; iteration < 8; ++iteration) {
        const double tc = std::min(hi, lo + (hi - lo) * theta * (1 + 1e-9) + 1e-15 * std::abs(hi));
        stepper.calc_state(tc, out);
        std::copy(out.begin(), out.end(), xs.begin());
        const double crossed = firstEvent(system, lo, xlo, tc, xs);
        if (crossed < 1.0) {  // still past the crossing, by more than the system accepts
            hi = tc;
            xhi = xs;
            theta = crossed;
        } else if (firstEvent(system, t0, x0, tc, xs) >= 1.0 && firstEvent(system, tc, xs, hi, xhi) < 1.0) {
            lo = tc;  // not yet crossed: it is between tc and hi
            xlo = xs;
            theta = firstEvent(system, lo, xlo, hi, xhi);
        } else {
            return tc;  // crossed and located
        }
    }
    stepper.calc_state(hi, out);
    std::copy(out.begin(), out.end(), xs.begin());
    return hi;
}

// The piece of a system with corners from t on (OdeSystem::enterSegment); true when it changed.
inline bool enterSegment(OdeSystem& system, double t) { return system.hasCorners() && system.enterSegment(t); }

template <class DenseStepper, class System, class V>
void runDense(DenseStepper stepper, System rhs, OdeSystem& system, State& x, const std::vector<double>& times,
              const IntegrationSettings& settings, const OutputObserver& observe, const Guard& guard) {
    event(system, times.front(), x);
    enterSegment(system, times.front());
    if (!observe(times.front(), x)) return;
    V v(x.size()), out(x.size());
    std::copy(x.begin(), x.end(), v.begin());
    stepper.initialize(v, times.front(), settings.dt);
    State outState(x.size()), current(x.size()), start = x;
    size_t k = 1;
    while (k < times.size()) {
        const double t0 = stepper.current_time();
        // A corner at a known time ends the step exactly there.
        if (const double toCorner = system.hasCorners() ? system.nextCorner(t0) - t0 : stepper.current_time_step();
            toCorner < stepper.current_time_step()) {
            std::copy(stepper.current_state().begin(), stepper.current_state().end(), v.begin());
            stepper.initialize(v, t0, toCorner);
        }
        stepper.do_step(rhs);
        double t = stepper.current_time();
        guard.afterStep(t, stepper.current_time_step(), stepper.current_state());
        // With events or corners, the step ends where the first one is (the rest is dropped).
        if (locates(system)) t = locateEvent(stepper, system, start, t0, out, current);
        for (; k < times.size() && !ahead(times[k], t); ++k) {
            stepper.calc_state(times[k], out);
            std::copy(out.begin(), out.end(), outState.begin());
            x = outState;
            if (!observe(times[k], outState)) return;
        }
        if (locates(system)) {
            const bool relocated = t < stepper.current_time();
            if (relocated) ++guard.counts.eventSteps;
            const bool changed = system.afterStep(t, current);
            if (enterSegment(system, t) || changed || relocated) {
                std::copy(current.begin(), current.end(), v.begin());
                stepper.initialize(v, t, stepper.current_time_step());
            }
            start = current;
        }
    }
}

template <class ControlledStepper, class System, class V>
void runControlled(ControlledStepper stepper, System rhs, OdeSystem& system, State& x, const std::vector<double>& times,
                   const IntegrationSettings& settings, const OutputObserver& observe, const Guard& guard, IntegrationCounts& counts) {
    double t = times.front(), dt = settings.dt;
    event(system, t, x);
    enterSegment(system, t);
    if (!observe(t, x)) return;
    V v(x.size()), v0(x.size());
    std::copy(x.begin(), x.end(), v.begin());
    State x1(x.size());
    for (size_t k = 1; k < times.size(); ++k) {
        while (ahead(times[k], t)) {
            double h = std::min(dt, times[k] - t);  // end exactly on the output time, or a corner's
            if (system.hasCorners()) h = std::min(h, system.nextCorner(t) - t);
            const double t0 = t;
            if (locates(system)) v0 = v;
            if (stepper.try_step(rhs, v, t, h) == odeint::success) {
                if (locates(system)) {
                    // Event location: retry the step shorter until it ends just past the crossing.
                    dt = std::max(dt, h);
                    for (int retry = 0; retry < 8; ++retry) {
                        std::copy(v.begin(), v.end(), x1.begin());
                        const double theta = firstEvent(system, t0, x, t, x1);
                        if (theta >= 1.0) break;
                        if (retry == 0) ++counts.eventSteps;
                        double hr = (t - t0) * theta * (1 + 1e-9) + 1e-15 * std::max(1.0, std::abs(t0));
                        v = v0;
                        t = t0;
                        while (stepper.try_step(rhs, v, t, hr) != odeint::success) ++counts.rejectedSteps;
                    }
                    guard.afterStep(t, t - t0, v);
                    std::copy(v.begin(), v.end(), x.begin());
                    if (system.afterStep(t, x)) {
                        std::copy(x.begin(), x.end(), v.begin());
                        resetAfterEvent(stepper);
                    }
                    if (enterSegment(system, t)) resetAfterEvent(stepper);
                } else {
                    guard.afterStep(t, h, v);
                    dt = std::max(dt, h);
                }
            } else {
                ++counts.rejectedSteps;
                dt = h;
                if (dt < 1e-12 * std::max(1.0, std::abs(t))) guard.afterStep(t, dt, v);
            }
        }
        std::copy(v.begin(), v.end(), x.begin());
        if (!observe(times[k], x)) break;
    }
}

// The step grid of a fixed-step method from t0 to t1: t_k = t0 + k·dt for k < steps,
// computed from k (not accumulated), and t_steps = t1. When (t1 − t0)/dt is an integer
// (to 1e-9 relative) every step is dt; otherwise the last one is shorter, lastStep.
struct FixedStepGrid {
    FixedStepGrid(double t0, double t1, double dt) : t0(t0), t1(t1), dt(dt) {
        const double ratio = (t1 - t0) / dt, whole = std::round(ratio);
        if (whole >= 1 && std::abs(ratio - whole) <= 1e-9 * ratio) {
            steps = static_cast<long>(whole);
        } else {
            steps = static_cast<long>(std::floor(ratio)) + 1;
            lastStep = t1 - (t0 + static_cast<double>(steps - 1) * dt);
        }
    }
    double time(long k) const { return k >= steps ? t1 : t0 + static_cast<double>(k) * dt; }

    double t0, t1, dt;
    long steps = 0;
    double lastStep = 0.0;  // 0: t1 − t0 is a multiple of dt
};

// Cubic Hermite interpolation inside a step from (x0, f0) to (x1, f1) of length h, f = ẋ,
// at θ ∈ (0, 1), per component with Δ = x1 − x0:
//   x(θ) = x0 + θ Δ + θ (θ − 1) [(1 − 2θ) Δ + (θ − 1) h f0 + θ h f1],
// the cubic with both ends' values and slopes: q from q and q̇, q̇ from q̇ and q̈, W from W
// and Qᵀq̇. Its error is O(h⁴), so it keeps rk4's order; a component at rest (Δ = 0,
// f0 = f1 = 0, e.g. a stuck joint) stays exactly constant.
inline void hermite(const State& x0, const State& f0, const State& x1, const State& f1, double h, double theta, State& out) {
    for (size_t i = 0; i < out.size(); ++i) {
        const double d = x1[i] - x0[i];
        out[i] = x0[i] + theta * d + theta * (theta - 1) * ((1 - 2 * theta) * d + (theta - 1) * h * f0[i] + theta * h * f1[i]);
    }
}

// Fixed-step methods step on FixedStepGrid whatever the output times are. An output time
// between two step ends gets the cubic Hermite interpolant of that step (above) from the
// states and right-hand sides at its ends; the right-hand side at a step end is the first
// stage of the next step (passed to do_step), so interpolation costs no evaluations but
// one at the very end when needed. Events: a step that crosses an event surface is retried
// shorter to end just past the crossing (OdeSystem::eventFraction); after the event the
// next step goes on to the same grid point, so the grid never shifts.
template <class Stepper>
void runFixed(Stepper stepper, OdeSystem& system, State& x, const std::vector<double>& times, const IntegrationSettings& settings,
              const OutputObserver& observe, const Guard& guard) {
    double t = times.front();
    event(system, t, x);
    if (!observe(t, x) || times.size() < 2) return;
    const FixedStepGrid grid(t, times.back(), settings.dt);
    IntegrationCounts& counts = guard.counts;
    State f(x.size()), x0(x.size()), f0(x.size()), sample(x.size());
    bool fresh = false;  // f = f(x, t)
    size_t next = 1;     // the next output time
    for (long k = 1; k <= grid.steps; ++k) {
        const double target = grid.time(k);
        if (k == grid.steps) counts.lastStep = grid.lastStep;
        while (ahead(target, t)) {
            if (!fresh) system(x, f, t);
            x0 = x;
            f0 = f;
            double h = target - t;
            stepper.do_step(std::ref(system), x, f0, t, h);
            for (int retry = 0; system.hasEvents() && retry < 8; ++retry) {
                const double theta = system.eventFraction(x0, x);
                if (theta >= 1.0) break;
                h = h * theta * (1 + 1e-9) + 1e-15 * std::max(1.0, std::abs(t));
                x = x0;
                stepper.do_step(std::ref(system), x, f0, t, h);
            }
            const double t1 = ahead(target, t + h) ? t + h : target;
            if (t1 != target) ++counts.eventSteps;
            guard.afterStep(t1, settings.dt, x);
            const bool inside = next < times.size() && ahead(t1, times[next]);
            fresh = inside || t1 < times.back();
            if (fresh) system(x, f, t1);
            for (; next < times.size() && ahead(t1, times[next]); ++next) {
                hermite(x0, f0, x, f, t1 - t, (times[next] - t) / (t1 - t), sample);
                ++counts.interpolatedOutputs;
                if (!observe(times[next], sample)) return;
            }
            t = t1;
            if (event(system, t, x)) fresh = false;
            for (; next < times.size() && !ahead(times[next], t); ++next)
                if (!observe(times[next], x)) return;
        }
    }
}

}  // namespace ll::detail

namespace ll::detail {
// In rosenbrock4.cpp.
void runRosenbrock4(OdeSystem& system, OdeState& x, const std::vector<double>& times, const IntegrationSettings& settings,
                    const OutputObserver& observe, const Guard& guard, IntegrationCounts& counts);
}  // namespace ll::detail
