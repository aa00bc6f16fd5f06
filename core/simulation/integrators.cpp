#include "core/simulation/integrators.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <boost/numeric/odeint.hpp>

namespace ll {
namespace odeint = boost::numeric::odeint;

const std::vector<IntegratorInfo>& integratorCatalogue() {
    static const std::vector<IntegratorInfo> catalogue = {
        {"euler", 1, false, "explicit Euler, fixed step",
         "teaching only: shows first-order error and energy growth; needs tiny steps"},
        {"midpoint", 2, false, "explicit midpoint (RK2), fixed step", "cheap smooth demos; error falls with dt²"},
        {"rk4", 4, false, "classical Runge–Kutta, fixed step",
         "smooth problems at a known step size, e.g. fixed-rate animation"},
        {"symplectic_euler", 1, false, "semi-implicit Euler, fixed step (q̇ first, then q with the new q̇)",
         "game/robot-simulator style; energy error stays bounded over long runs on conservative scenes"},
        {"cash_karp54", 5, true, "embedded Runge–Kutta 5(4), error controlled", "general purpose, non-stiff"},
        {"dopri5", 5, true, "Dormand–Prince 5(4) with dense output, error controlled",
         "the default: non-stiff scenes at moderate tolerances"},
        {"fehlberg78", 8, true, "Runge–Kutta–Fehlberg 7(8), error controlled", "tight tolerances on smooth scenes"},
        {"bulirsch_stoer", 0, true, "Bulirsch–Stoer extrapolation (variable order), error controlled",
         "very tight tolerances on smooth scenes"},
    };
    return catalogue;
}

const IntegratorInfo* findIntegrator(const std::string& name) {
    for (const IntegratorInfo& info : integratorCatalogue())
        if (info.name == name) return &info;
    return nullptr;
}

std::string integratorNames() {
    std::string names;
    for (const IntegratorInfo& info : integratorCatalogue()) names += (names.empty() ? "" : ", ") + info.name;
    return names;
}

namespace {

using State = OdeState;

std::string describeState(const State& x) {
    std::ostringstream s;
    s.precision(6);
    s << "[";
    for (size_t i = 0; i < x.size(); ++i) s << (i ? ", " : "") << x[i];
    s << "]";
    return s.str();
}

bool allFinite(const State& x) {
    return std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); });
}

// Shared guards for every driver: finite state, a step size that has not collapsed,
// and a bounded number of steps.
struct Guard {
    const IntegrationSettings& settings;
    IntegrationCounts& counts;

    void afterStep(double t, double dt, const State& x) const {
        if (!allFinite(x))
            throw IntegrationError(t, x,
                                   "state became non-finite at t = " + std::to_string(t) + " s (state " + describeState(x) +
                                       ") with " + settings.integrator + (findIntegrator(settings.integrator)->adaptive
                                                                              ? ": tighten the tolerances"
                                                                              : ": the step is too large for this scene; reduce dt or use an adaptive integrator such as dopri5"));
        if (dt < 1e-12 * std::max(1.0, std::abs(t)))
            throw IntegrationError(t, x,
                                   "step size collapsed to " + std::to_string(dt) + " s at t = " + std::to_string(t) +
                                       " s (state " + describeState(x) +
                                       "): the scene is stiff or discontinuous here; loosen the tolerances, soften "
                                       "stiff springs or friction, or use an implicit integrator");
        if (++counts.steps > settings.maxSteps)
            throw IntegrationError(t, x,
                                   "gave up after " + std::to_string(settings.maxSteps) + " steps at t = " +
                                       std::to_string(t) + " s: the scene is probably stiff (a fast spring or "
                                       "friction); loosen the tolerances, shorten the run or soften the stiff effect");
    }
};

bool ahead(double target, double t) { return target - t > 1e-12 * std::max(1.0, std::abs(target)); }

template <class DenseStepper>
void runDense(DenseStepper stepper, OdeSystem& system, State& x, const std::vector<double>& times,
              const IntegrationSettings& settings, const OutputObserver& observe, IntegrationCounts& counts) {
    const Guard guard{settings, counts};
    if (!observe(times.front(), x)) return;
    stepper.initialize(x, times.front(), settings.dt);
    State out(x.size());
    for (size_t k = 1; k < times.size(); ++k) {
        while (ahead(times[k], stepper.current_time())) {
            stepper.do_step(std::ref(system));
            guard.afterStep(stepper.current_time(), stepper.current_time_step(), stepper.current_state());
        }
        stepper.calc_state(times[k], out);
        if (!observe(times[k], out)) break;
    }
    stepper.calc_state(times.back(), x);
}

template <class ControlledStepper>
void runControlled(ControlledStepper stepper, OdeSystem& system, State& x, const std::vector<double>& times,
                   const IntegrationSettings& settings, const OutputObserver& observe, IntegrationCounts& counts) {
    const Guard guard{settings, counts};
    double t = times.front(), dt = settings.dt;
    if (!observe(t, x)) return;
    for (size_t k = 1; k < times.size(); ++k) {
        while (ahead(times[k], t)) {
            double h = std::min(dt, times[k] - t);  // end exactly on the output time
            if (stepper.try_step(std::ref(system), x, t, h) == odeint::success) {
                guard.afterStep(t, h, x);
                dt = std::max(dt, h);
            } else {
                ++counts.rejectedSteps;
                dt = h;
                if (dt < 1e-12 * std::max(1.0, std::abs(t))) guard.afterStep(t, dt, x);
            }
        }
        if (!observe(times[k], x)) break;
    }
}

template <class Stepper>
void runFixed(Stepper stepper, OdeSystem& system, State& x, const std::vector<double>& times,
              const IntegrationSettings& settings, const OutputObserver& observe, IntegrationCounts& counts) {
    const Guard guard{settings, counts};
    double t = times.front();
    if (!observe(t, x)) return;
    for (size_t k = 1; k < times.size(); ++k) {
        while (ahead(times[k], t)) {
            const double h = std::min(settings.dt, times[k] - t);
            stepper.do_step(std::ref(system), x, t, h);
            t += h;
            guard.afterStep(t, settings.dt, x);
        }
        t = times[k];
        if (!observe(t, x)) break;
    }
}

// Semi-implicit Euler: q̇_{k+1} = q̇_k + h q̈(q_k, q̇_k), q_{k+1} = q_k + h q̇_{k+1}.
// Odeint's symplectic_euler needs a separable Hamiltonian system; robots are not
// (q̈ depends on q̇ through C), so this is written out here.
class SymplecticEuler {
public:
    explicit SymplecticEuler(int n) : n_(n) {}
    void do_step(std::reference_wrapper<OdeSystem> system, State& x, double t, double h) {
        dxdt_.resize(x.size());
        system.get()(x, dxdt_, t);
        for (int i = 0; i < n_; ++i) x[n_ + i] += h * dxdt_[n_ + i];
        for (int i = 0; i < n_; ++i) x[i] += h * x[n_ + i];
        for (size_t i = 2 * n_; i < x.size(); ++i) x[i] += h * dxdt_[i];
    }

private:
    int n_;
    State dxdt_;
};

// Explicit midpoint: k1 = f(x), x + h f(x + h/2 k1), as an Odeint generic Runge–Kutta tableau.
using MidpointBase = odeint::explicit_generic_rk<2, 2, State, double, State, double>;
class Midpoint : public MidpointBase {
public:
    Midpoint() : MidpointBase(coefA(), {{0.0, 1.0}}, {{0.0, 0.5}}) {}

private:
    static MidpointBase::coef_a_type coefA() {
        const boost::array<double, 1> a1 = {{0.5}};
        return MidpointBase::coef_a_type(a1);
    }
};

}  // namespace

IntegrationCounts integrate(OdeSystem& system, OdeState& x, const std::vector<double>& times,
                            const IntegrationSettings& settings, const OutputObserver& observe) {
    if (!findIntegrator(settings.integrator))
        throw std::invalid_argument("unknown integrator '" + settings.integrator + "' (known: " + integratorNames() + ")");
    if (times.empty()) return {};
    IntegrationCounts counts;
    const std::string& name = settings.integrator;
    const double abs = settings.absTol, rel = settings.relTol;
    if (name == "euler")
        runFixed(odeint::euler<State>(), system, x, times, settings, observe, counts);
    else if (name == "midpoint")
        runFixed(Midpoint(), system, x, times, settings, observe, counts);
    else if (name == "rk4")
        runFixed(odeint::runge_kutta4<State>(), system, x, times, settings, observe, counts);
    else if (name == "symplectic_euler")
        runFixed(SymplecticEuler(system.coordinates()), system, x, times, settings, observe, counts);
    else if (name == "cash_karp54")
        runControlled(odeint::make_controlled(abs, rel, odeint::runge_kutta_cash_karp54<State>()), system, x, times,
                      settings, observe, counts);
    else if (name == "dopri5")
        runDense(odeint::make_dense_output(abs, rel, odeint::runge_kutta_dopri5<State>()), system, x, times, settings,
                 observe, counts);
    else if (name == "fehlberg78")
        runControlled(odeint::make_controlled(abs, rel, odeint::runge_kutta_fehlberg78<State>()), system, x, times,
                      settings, observe, counts);
    else if (name == "bulirsch_stoer")
        // Stepped to each output time: its dense output misses the tolerance by up to 50x.
        runControlled(odeint::bulirsch_stoer<State>(abs, rel), system, x, times, settings, observe, counts);
    return counts;
}

}  // namespace ll
