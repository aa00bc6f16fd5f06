#pragma once
// The interface every integrated system offers: a robot from its DH table or a
// Lagrangian typed by hand. One virtual call per right-hand side is negligible
// beside the dynamics it evaluates, and lets the integrators compile once.
#include <limits>
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
    // Corners: where the right-hand side does not change mode but is not smooth (a
    // controller's reference changing phase or jumping, a torque reaching or leaving its
    // limit). An error-controlled step across one is accepted only when short, and is less
    // accurate; the adaptive drivers end a step at each instead. Fixed-step methods keep
    // their grid and pass them. Corners at known times: the first after t (+inf: none),
    // where the drivers end a step exactly. Corners that depend on the state: for a step
    // from (t0, x0) to (t1, x1), the fraction (0, 1) of it at which the first lies, or 1
    // when none does or the step ends at it already (located as events are). Not const:
    // it may evaluate the system.
    virtual bool hasCorners() const { return false; }
    virtual double nextCorner(double /*t*/) const { return std::numeric_limits<double>::infinity(); }
    virtual double cornerFraction(double /*t0*/, const OdeState& /*x0*/, double /*t1*/, const OdeState& /*x1*/) { return 1.0; }
    // A corner at a known time may be a jump (a step reference, a trapezoid's
    // acceleration): every stage of a step that ends on it must see the side the step
    // started on, or its error estimate sees the jump and the step is refused however
    // short. The adaptive drivers call this at the start and after every accepted step of
    // a system with corners: from t to the next corner the right-hand side keeps to that
    // smooth piece, one-sided at its ends. True when the piece changed (the driver restarts
    // its stepper there).
    virtual bool enterSegment(double /*t*/) { return false; }
};

}  // namespace ll
