#pragma once
// The friction laws of Q, written once for every scalar: doubles (simulation, eval)
// and GiNaC expressions (the symbolic derivations, where ADL finds GiNaC's tanh):
//   viscous                Q_i = −b q̇_i
//   Coulomb, tanh model    Q_i = −F_c tanh(q̇_i / v_s)
// (The stick model's set-valued law lives in the integrator events, RobotOde.)
#include <cmath>

namespace ll {

template <class Scalar>
Scalar viscousFrictionForce(const Scalar& coefficient, const Scalar& qd) {
    return -coefficient * qd;
}

template <class Scalar>
Scalar tanhCoulombForce(const Scalar& force, const Scalar& qd, const Scalar& smoothing) {
    using std::tanh;
    return -force * tanh(qd / smoothing);
}

}  // namespace ll
