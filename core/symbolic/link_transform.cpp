#include "core/symbolic/link_transform.hpp"

#include "core/kinematics/dh_transform.hpp"

namespace ll::symbolic {

GiNaC::matrix linkTransform(DhConvention convention, const SymbolicJoint& j, const TrigContext& tc, int i) {
    GiNaC::ex ct, st, d = j.d;
    if (j.type == JointType::Revolute) {
        ct = GiNaC::cos(j.theta) * tc.c(i) - GiNaC::sin(j.theta) * tc.s(i);
        st = GiNaC::sin(j.theta) * tc.c(i) + GiNaC::cos(j.theta) * tc.s(i);
    } else {
        ct = GiNaC::cos(j.theta);
        st = GiNaC::sin(j.theta);
        d = j.d + tc.q(i);
    }
    GiNaC::matrix A(4, 4);
    dhTransform<GiNaC::ex>(convention, j.a, d, ct, st, GiNaC::cos(j.alpha), GiNaC::sin(j.alpha), A);
    return A;
}

GiNaC::matrix inverseTransform(const GiNaC::matrix& T) {
    GiNaC::matrix inv(4, 4);
    for (int r = 0; r < 3; ++r) {
        GiNaC::ex t = 0;
        for (int c = 0; c < 3; ++c) {
            inv(r, c) = T(c, r);
            t -= T(c, r) * T(c, 3);
        }
        inv(r, 3) = t;
    }
    inv(3, 3) = 1;
    return inv;
}

}  // namespace ll::symbolic
