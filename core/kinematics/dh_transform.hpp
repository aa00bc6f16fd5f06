#pragma once
// The DH link transform A_i, written once for any scalar type (double here, GiNaC
// expressions in the symbolic derivation). It takes the cosines and sines rather
// than the angles, so a symbolic caller can pass the symbols c_i, s_i.
#include "core/model/dh_row.hpp"

namespace ll {

// Fills the 4x4 homogeneous matrix A (anything with A(r, c) assignment) of one DH row:
//   standard: Rot_z(θ) Trans_z(d) Trans_x(a) Rot_x(α)
//   modified: Rot_x(α) Trans_x(a) Rot_z(θ) Trans_z(d)     (a, α are a_{i-1}, α_{i-1})
// with ct = cos θ, st = sin θ, ca = cos α, sa = sin α (θ, d including the joint variable).
template <class Scalar, class Matrix4>
void dhTransform(DhConvention convention, const Scalar& a, const Scalar& d, const Scalar& ct, const Scalar& st, const Scalar& ca,
                 const Scalar& sa, Matrix4& A) {
    const Scalar zero(0), one(1);
    if (convention == DhConvention::Standard) {
        A(0, 0) = ct;
        A(0, 1) = -st * ca;
        A(0, 2) = st * sa;
        A(0, 3) = a * ct;
        A(1, 0) = st;
        A(1, 1) = ct * ca;
        A(1, 2) = -ct * sa;
        A(1, 3) = a * st;
        A(2, 0) = zero;
        A(2, 1) = sa;
        A(2, 2) = ca;
        A(2, 3) = d;
    } else {
        A(0, 0) = ct;
        A(0, 1) = -st;
        A(0, 2) = zero;
        A(0, 3) = a;
        A(1, 0) = st * ca;
        A(1, 1) = ct * ca;
        A(1, 2) = -sa;
        A(1, 3) = -sa * d;
        A(2, 0) = st * sa;
        A(2, 1) = ct * sa;
        A(2, 2) = ca;
        A(2, 3) = ca * d;
    }
    A(3, 0) = zero;
    A(3, 1) = zero;
    A(3, 2) = zero;
    A(3, 3) = one;
}

}  // namespace ll
