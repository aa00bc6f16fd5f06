#pragma once
// The Christoffel construction of the Coriolis/centrifugal matrix from the partial
// derivatives of B, written once for every scalar: doubles (core/dynamics/coriolis)
// and GiNaC expressions (the symbolic derivations of robots and Lagrangian systems):
//   Γ_ijk = ½ (∂b_ij/∂q_k + ∂b_ik/∂q_j − ∂b_jk/∂q_i),   c_ij = Σ_k Γ_ijk q̇_k
// (course notes; Siciliano (7.45)). With this choice Ḃ − 2C is skew-symmetric.
// dB[k] is ∂B/∂q_k, indexable as dB[k](i, j); qd[k] is q̇_k.

namespace ll {

// Γ_ijk, the Christoffel symbol of the first kind.
template <class Scalar, class Derivatives>
Scalar christoffelSymbol(const Derivatives& dB, int i, int j, int k) {
    return Scalar(dB[k](i, j) + dB[j](i, k) - dB[i](j, k)) / 2;
}

// C(i, j) = c_ij for 0 <= i, j < n (C sized n×n by the caller).
template <class Scalar, class Derivatives, class Velocities, class Matrix>
void christoffelMatrix(int n, const Derivatives& dB, const Velocities& qd, Matrix& C) {
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            Scalar c = 0;
            for (int k = 0; k < n; ++k) c += christoffelSymbol<Scalar>(dB, i, j, k) * qd[k];
            C(i, j) = c;
        }
}

}  // namespace ll
