// rosenbrock4 behind integrate(): Odeint's linearly implicit Rosenbrock 4(3) with
// error control, on uBLAS vectors, with the Jacobian by central differences.
// Compiled as C++17 (see integration_drivers.hpp).
#include <boost/numeric/odeint/stepper/rosenbrock4.hpp>
#include <boost/numeric/odeint/stepper/rosenbrock4_controller.hpp>

#include "core/simulation/integration_drivers.hpp"

namespace ll::detail {
namespace {

using UVector = boost::numeric::ublas::vector<double>;
using UMatrix = boost::numeric::ublas::matrix<double>;

// rosenbrock4 works on ublas vectors and needs (system, Jacobian).
struct UblasSystem {
    OdeSystem* system;
    State* xs;
    State* dxs;
    void operator()(const UVector& x, UVector& dxdt, double t) const {
        std::copy(x.begin(), x.end(), xs->begin());
        (*system)(*xs, *dxs, t);
        std::copy(dxs->begin(), dxs->end(), dxdt.begin());
    }
};

struct UblasJacobian {
    OdeSystem* system;
    IntegrationCounts* counts;
    void operator()(const UVector& x, UMatrix& J, const double& t, UVector& dfdt) const {
        Eigen::MatrixXd Je;
        Eigen::VectorXd dt;
        numericJacobian(*system, toState(x), t, Je, &dt);
        ++counts->jacobians;
        for (int r = 0; r < Je.rows(); ++r) {
            dfdt[r] = dt[r];
            for (int c = 0; c < Je.cols(); ++c) J(r, c) = Je(r, c);
        }
    }
};

}  // namespace

void runRosenbrock4(OdeSystem& system, State& x, const std::vector<double>& times, const IntegrationSettings& settings,
                    const OutputObserver& observe, const Guard& guard, IntegrationCounts& counts) {
    State xs(x.size()), dxs(x.size());
    const auto pair = std::make_pair(UblasSystem{&system, &xs, &dxs}, UblasJacobian{&system, &counts});
    using Controller = odeint::rosenbrock4_controller<odeint::rosenbrock4<double>>;
    // Stepped to each output time, like Bulirsch–Stoer: its dense output is only third order.
    runControlled<Controller, decltype(pair), UVector>(Controller(settings.absTol, settings.relTol), pair, system, x, times, settings,
                                                       observe, guard, counts);
}

}  // namespace ll::detail
