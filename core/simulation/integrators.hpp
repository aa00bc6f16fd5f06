#pragma once
// The integrators, chosen by name at run time (scene files, command line, GUI),
// all driven through one function so every caller gets the same error handling,
// cancellation and cost accounting.
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

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
std::string integratorNames();                                   // "euler, midpoint, ..."

struct IntegrationSettings {
    std::string integrator = "dopri5";
    double absTol = 1e-8;
    double relTol = 1e-8;
    double dt = 1e-3;       // fixed step, or the first trial step of adaptive methods
    long maxSteps = 20'000'000;
};

struct IntegrationCounts {
    long steps = 0;
    long rejectedSteps = 0;
};

// Thrown when integration cannot go on: non-finite state, step-size collapse,
// step budget exhausted. what() says the time, the state and what to try.
class IntegrationError : public std::runtime_error {
public:
    IntegrationError(double t, OdeState x, const std::string& message)
        : std::runtime_error(message), t_(t), x_(std::move(x)) {}
    double time() const { return t_; }
    const OdeState& state() const { return x_; }

private:
    double t_;
    OdeState x_;
};

// Observer at each output time (including times.front()); return false to stop
// (cancellation). Called with the state at exactly that time (dense output or a
// step that ends on it).
using OutputObserver = std::function<bool(double t, const OdeState& x)>;

// Integrates x from times.front() through every time in `times` (increasing).
// Throws IntegrationError, std::invalid_argument for an unknown integrator name.
IntegrationCounts integrate(OdeSystem& system, OdeState& x, const std::vector<double>& times,
                            const IntegrationSettings& settings, const OutputObserver& observe);

}  // namespace ll
