#include "core/simulation/integrators.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <limits>
#include <numbers>

#include <boost/numeric/odeint.hpp>

#include "core/simulation/integration_drivers.hpp"

namespace ll {
namespace odeint = boost::numeric::odeint;

const std::vector<IntegratorInfo>& integratorCatalogue() {
    static const std::vector<IntegratorInfo> catalogue = {
        {"euler", 1, false, "explicit Euler, fixed step", "teaching only: shows first-order error and energy growth; needs tiny steps"},
        {"midpoint", 2, false, "explicit midpoint (RK2), fixed step", "cheap smooth demos; error falls with dt²"},
        {"rk4", 4, false, "classical Runge–Kutta, fixed step", "smooth problems at a known step size, e.g. fixed-rate animation"},
        {"symplectic_euler", 1, false, "semi-implicit Euler, fixed step (q̇ first, then q with the new q̇)",
         "game/robot-simulator style; energy error stays bounded over long runs on conservative scenes"},
        {"cash_karp54", 5, true, "embedded Runge–Kutta 5(4), error controlled", "general purpose, non-stiff"},
        {"dopri5", 5, true, "Dormand–Prince 5(4) with dense output, error controlled",
         "the default: non-stiff scenes at moderate tolerances"},
        {"fehlberg78", 8, true, "Runge–Kutta–Fehlberg 7(8), error controlled", "tight tolerances on smooth scenes"},
        {"bulirsch_stoer", 0, true, "Bulirsch–Stoer extrapolation (variable order), error controlled",
         "very tight tolerances on smooth scenes"},
        {"rosenbrock4", 4, true, "linearly implicit Rosenbrock 4(3), error controlled; Jacobian by central differences",
         "stiff scenes (a stiff joint spring on a slow arm) where explicit methods crawl at their stability limit"},
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

// Semi-implicit Euler: q̇_{k+1} = q̇_k + h q̈(q_k, q̇_k), q_{k+1} = q_k + h q̇_{k+1}.
// Odeint's symplectic_euler needs a separable Hamiltonian system; robots are not
// (q̈ depends on q̇ through C), so this is written out here.
class SymplecticEuler {
public:
    explicit SymplecticEuler(int n) : n_(n) {}
    // dxdt = f(x, t), given by the driver (it is the right-hand side at the last step's end).
    void do_step(std::reference_wrapper<OdeSystem>, State& x, const State& dxdt, double, double h) const {
        for (int i = 0; i < n_; ++i) x[n_ + i] += h * dxdt[n_ + i];
        for (int i = 0; i < n_; ++i) x[i] += h * x[n_ + i];
        for (size_t i = 2 * n_; i < x.size(); ++i) x[i] += h * dxdt[i];
    }

private:
    int n_;
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

void numericJacobian(OdeSystem& system, const OdeState& x, double t, Eigen::MatrixXd& J, Eigen::VectorXd* dfdt) {
    const int size = static_cast<int>(x.size()), n = system.coordinates();
    const double cbrtEps = std::cbrt(std::numeric_limits<double>::epsilon());
    J.setZero(size, size);
    State xp = x, fp(size), fm(size);
    for (int i = 0; i < n; ++i) J(i, n + i) = 1.0;  // q' = q̇, exactly
    for (int c = 0; c < size; ++c) {
        const double h0 = cbrtEps * std::max(std::abs(x[c]), 1.0);
        xp[c] = x[c] + h0;
        const double hp = xp[c] - x[c];  // exactly representable steps
        system(xp, fp, t);
        xp[c] = x[c] - h0;
        const double hm = x[c] - xp[c];
        system(xp, fm, t);
        xp[c] = x[c];
        for (int r = n; r < size; ++r) J(r, c) = (fp[r] - fm[r]) / (hp + hm);
    }
    if (dfdt) {
        dfdt->setZero(size);
        const double h = cbrtEps * std::max(std::abs(t), 1.0);
        system(x, fp, t + h);
        system(x, fm, t - h);
        for (int r = n; r < size; ++r) (*dfdt)[r] = (fp[r] - fm[r]) / (2 * h);
    }
}

using namespace detail;

IntegrationCounts integrate(OdeSystem& system, OdeState& x, const std::vector<double>& times, const IntegrationSettings& settings,
                            const OutputObserver& observe) {
    if (!findIntegrator(settings.integrator))
        throw std::invalid_argument("unknown integrator '" + settings.integrator + "' (known: " + integratorNames() + ")");
    if (times.empty()) return {};
    IntegrationCounts counts;
    StiffnessMonitor stiffness(system, settings, times.front(), times.back(), counts);
    const Guard guard{settings, counts, stiffness};
    const std::string& name = settings.integrator;
    const double abs = settings.absTol, rel = settings.relTol;
    const auto rhs = std::ref(system);
    try {
        if (name == "euler") runFixed(odeint::euler<State>(), system, x, times, settings, observe, guard);
        else if (name == "midpoint") runFixed(Midpoint(), system, x, times, settings, observe, guard);
        else if (name == "rk4") runFixed(odeint::runge_kutta4<State>(), system, x, times, settings, observe, guard);
        else if (name == "symplectic_euler") runFixed(SymplecticEuler(system.coordinates()), system, x, times, settings, observe, guard);
        else if (name == "cash_karp54")
            runControlled<decltype(odeint::make_controlled(abs, rel, odeint::runge_kutta_cash_karp54<State>())), decltype(rhs), State>(
                odeint::make_controlled(abs, rel, odeint::runge_kutta_cash_karp54<State>()), rhs, system, x, times, settings, observe,
                guard, counts);
        else if (name == "dopri5")
            runDense<decltype(odeint::make_dense_output(abs, rel, odeint::runge_kutta_dopri5<State>())), decltype(rhs), State>(
                odeint::make_dense_output(abs, rel, odeint::runge_kutta_dopri5<State>()), rhs, system, x, times, settings, observe, guard);
        else if (name == "fehlberg78")
            runControlled<decltype(odeint::make_controlled(abs, rel, odeint::runge_kutta_fehlberg78<State>())), decltype(rhs), State>(
                odeint::make_controlled(abs, rel, odeint::runge_kutta_fehlberg78<State>()), rhs, system, x, times, settings, observe, guard,
                counts);
        else if (name == "bulirsch_stoer")
            // Stepped to each output time: its dense output misses the tolerance by up to 50x.
            runControlled<odeint::bulirsch_stoer<State>, decltype(rhs), State>(odeint::bulirsch_stoer<State>(abs, rel), rhs, system, x,
                                                                               times, settings, observe, guard, counts);
        else if (name == "rosenbrock4") detail::runRosenbrock4(system, x, times, settings, observe, guard, counts);
    } catch (IntegrationError& e) {
        e.setCounts(counts);
        throw;
    }
    return counts;
}

}  // namespace ll
