#pragma once
// Spatial (6D) vectors and rigid-body inertia, all expressed in the world frame at
// its origin (Featherstone's "world coordinates"). Working in one frame lets the
// composite inertias be plain sums and needs no frame transforms in the recursions.
// Motion vector m = [ω; v_O] (v_O: velocity of the body point at the origin).
// Force vector f = [n_O; f] (n_O: moment about the origin).
// Reference: R. Featherstone, Rigid Body Dynamics Algorithms (RBDA), 2008, ch. 2.
#include <Eigen/Core>

namespace ll {

using Vector6d = Eigen::Matrix<double, 6, 1>;

inline Eigen::Vector3d angular(const Vector6d& m) { return m.head<3>(); }
inline Eigen::Vector3d linear(const Vector6d& m) { return m.tail<3>(); }

// m1 × m2 (motion cross motion): the rate of change of m2 carried by a body moving with m1.
inline Vector6d crossMotion(const Vector6d& m1, const Vector6d& m2) {
    Vector6d r;
    r.head<3>() = m1.head<3>().cross(m2.head<3>());
    r.tail<3>() = m1.head<3>().cross(m2.tail<3>()) + m1.tail<3>().cross(m2.head<3>());
    return r;
}

// m ×* f (motion cross force).
inline Vector6d crossForce(const Vector6d& m, const Vector6d& f) {
    Vector6d r;
    r.head<3>() = m.head<3>().cross(f.head<3>()) + m.tail<3>().cross(f.tail<3>());
    r.tail<3>() = m.head<3>().cross(f.tail<3>());
    return r;
}

// Rigid-body inertia about the world origin: mass m, first moment h = m p_c and
// rotational inertia about the origin Ī_O = R I_c Rᵀ + m(|p_c|² 1 − p_c p_cᵀ).
struct SpatialInertia {
    double m = 0.0;
    Eigen::Vector3d h = Eigen::Vector3d::Zero();
    Eigen::Matrix3d I = Eigen::Matrix3d::Zero();

    // Momentum of the body moving with v: [Ī ω + h × v_O; m v_O − h × ω].
    Vector6d operator*(const Vector6d& v) const {
        Vector6d f;
        f.head<3>() = I * v.head<3>() + h.cross(v.tail<3>());
        f.tail<3>() = m * v.tail<3>() - h.cross(v.head<3>());
        return f;
    }
    SpatialInertia& operator+=(const SpatialInertia& o) {
        m += o.m;
        h += o.h;
        I += o.I;
        return *this;
    }
};

// Inertia of a body with mass m, COM p_c (world) and COM inertia Ic_world (world axes).
inline SpatialInertia spatialInertiaAtOrigin(double m, const Eigen::Vector3d& p_c, const Eigen::Matrix3d& Ic_world) {
    SpatialInertia I;
    I.m = m;
    I.h = m * p_c;
    I.I = Ic_world + m * (p_c.squaredNorm() * Eigen::Matrix3d::Identity() - p_c * p_c.transpose());
    return I;
}

}  // namespace ll
