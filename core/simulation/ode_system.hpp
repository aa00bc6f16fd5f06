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
};

}  // namespace ll
