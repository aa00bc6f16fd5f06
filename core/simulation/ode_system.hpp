#pragma once
// The interface every integrated system offers: a robot from its DH table or a
// Lagrangian typed by hand. One virtual call per right-hand side is negligible
// beside the dynamics it evaluates, and lets the integrators compile once.
#include <vector>

namespace ll {

using OdeState = std::vector<double>;

class OdeSystem {
public:
    virtual ~OdeSystem() = default;
    // dxdt = f(x, t); x and dxdt have the same size.
    virtual void operator()(const OdeState& x, OdeState& dxdt, double t) = 0;
    // The state is laid out [q (n); q̇ (n); extras]; the semi-implicit Euler needs n.
    virtual int coordinates() const = 0;
    // Events between steps (e.g. a joint that sticks by Coulomb friction): called by
    // every driver at the start and after each accepted step with the state at t.
    // It may change the system's mode and x.
    virtual bool afterStep(double /*t*/, OdeState& /*x*/) { return false; }
    // It returns true when it changed x or the system's mode (the right-hand side), and
    // the driver then restarts its stepper from the new state.
    // False when afterStep never does anything (drivers then skip calling it).
    virtual bool hasEvents() const { return false; }
    // Event location: for a step from x0 to x1, the estimated fraction (0, 1) of the
    // step at which an event surface was crossed (the driver then retries the step that
    // much shorter, so the event is handled where it happens), or 1 when none was
    // crossed or the crossing is already located closely enough.
    virtual double eventFraction(const OdeState& /*x0*/, const OdeState& /*x1*/) const { return 1.0; }
};

}  // namespace ll
