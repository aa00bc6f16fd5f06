#pragma once
// The integrators, chosen by name at run time (scene files, command line, GUI),
// all driven through one function so every caller gets the same error handling,
// cancellation and cost accounting.
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/model/integration_settings.hpp"
#include "core/model/message.hpp"
#include "core/simulation/ode_system.hpp"

namespace ll {

struct IntegratorInfo {
    std::string name;
    int order = 0;
    bool adaptive = false;  // error-controlled step size
    std::string kind;       // e.g. "explicit Runge–Kutta, fixed step"
    std::string whenToUse;
};

const std::vector<IntegratorInfo>& integratorCatalogue();
const IntegratorInfo* findIntegrator(const std::string& name);  // nullptr if unknown
std::string integratorNames();                                  // "euler, midpoint, ..."

struct IntegrationCounts {
    long steps = 0;
    long rejectedSteps = 0;
    long jacobians = 0;  // rosenbrock4 and the stiffness monitor (each costs 4n+2 evaluations)
    long eventSteps = 0;  // steps that ended early at a located event or (adaptive methods) corner (included in steps)
    // Fixed-step methods only (see FixedStepGrid in integration_drivers.hpp):
    double lastStep = 0.0;         // a last step shorter than dt [s], when T − t0 is not a multiple of dt; else 0
    long interpolatedOutputs = 0;  // output samples between step ends (cubic Hermite interpolation)
};

// ∂f/∂x by central differences, step h_j = ε^(1/3) max(|x_j|, 1) per component (exact
// [0 I 0] for the rows q' = q̇), and ∂f/∂t (if dfdt is given) the same way.
void numericJacobian(OdeSystem& system, const OdeState& x, double t, Eigen::MatrixXd& J, Eigen::VectorXd* dfdt = nullptr);

// Thrown when integration cannot go on: non-finite state, step-size collapse,
// step budget exhausted. message() says the time, the state and what to try; what() is
// its English words.
class IntegrationError : public std::runtime_error {
public:
    IntegrationError(double t, OdeState x, Message message)
        : std::runtime_error(message.english()), message_(std::move(message)), t_(t), x_(std::move(x)) {}
    const Message& message() const { return message_; }
    double time() const { return t_; }
    const OdeState& state() const { return x_; }
    // The work done before it stopped (set by integrate()).
    const IntegrationCounts& counts() const { return counts_; }
    void setCounts(const IntegrationCounts& counts) { counts_ = counts; }

private:
    Message message_;
    double t_;
    OdeState x_;
    IntegrationCounts counts_;
};

// Observer at each output time (including times.front()); return false to stop
// (cancellation). Called with the state at exactly that time: a step that ends on it,
// dense output (dopri5), or for fixed-step methods, whose steps do not depend on the
// output times, cubic Hermite interpolation between the two step ends around it.
using OutputObserver = std::function<bool(double t, const OdeState& x)>;

// Integrates x from times.front() through every time in `times` (increasing).
// Throws IntegrationError, std::invalid_argument for an unknown integrator name.
IntegrationCounts integrate(OdeSystem& system, OdeState& x, const std::vector<double>& times, const IntegrationSettings& settings,
                            const OutputObserver& observe);

}  // namespace ll
