#pragma once
// A 3-vector of GiNaC expressions (a position, an axis, an angular velocity in the
// derivation) and the little algebra the derivation writes with it.
#include <array>
#include <ginac/ginac.h>

namespace ll::symbolic {

using Vec3 = std::array<GiNaC::ex, 3>;

inline Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline GiNaC::ex dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace ll::symbolic
