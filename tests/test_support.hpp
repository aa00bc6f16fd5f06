#pragma once
// Shared fixtures for the tests: textbook robots built in code and random robots
// and states with fixed seeds (reproducible failures).
#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "core/model/effects.hpp"
#include "core/model/robot_model.hpp"

namespace ll::test {

// Planar 2R arm of Siciliano et al. §7.3.2: links of length a_i, COM at ℓ_ci from
// joint i along the link, inertia I_i about the COM around z.
struct Planar2R {
    double a1 = 1.0, a2 = 0.8, l1 = 0.45, l2 = 0.35, m1 = 2.0, m2 = 1.5, I1 = 0.17, I2 = 0.08;

    RobotModel model() const {
        RobotModel robot;
        robot.name = "planar 2R";
        robot.joints.resize(2);
        robot.joints[0].dh.a = a1;
        robot.joints[0].link.mass = m1;
        robot.joints[0].link.com = {-(a1 - l1), 0, 0};
        robot.joints[0].link.inertia.diagonal() << 0.01, I1, I1;
        robot.joints[1].dh.a = a2;
        robot.joints[1].link.mass = m2;
        robot.joints[1].link.com = {-(a2 - l2), 0, 0};
        robot.joints[1].link.inertia.diagonal() << 0.01, I2, I2;
        return robot;
    }
};

// The course notes' rotational mass–spring pair as a coaxial chain: θ1 = q1,
// θ2 = q1 + q2 (q2 relative), K1 on joint 1, K2 on joint 2.
struct MassSpringPair {
    double I1 = 0.5, I2 = 0.2, K1 = 10.0, K2 = 4.0;

    RobotModel model() const {
        RobotModel robot;
        robot.joints.resize(2);
        robot.joints[0].link.inertia(2, 2) = I1;
        robot.joints[1].link.inertia(2, 2) = I2;
        return robot;
    }
    Effects effects() const {
        Effects e;
        e.springs = {{0, K1, 0.0}, {1, K2, 0.0}};
        return e;
    }
};

// A random symmetric positive definite inertia with products of inertia:
// R diag(λ) Rᵀ with principal moments that satisfy the triangle inequality.
inline Eigen::Matrix3d randomInertia(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0.05, 0.5);
    const double a = u(rng), b = u(rng);
    std::uniform_real_distribution<double> c(std::abs(a - b) + 0.01, a + b);
    const Eigen::Vector3d moments(a, b, c(rng));
    const Eigen::Matrix3d R = Eigen::Quaterniond::UnitRandom().toRotationMatrix();
    return R * moments.asDiagonal() * R.transpose();
}

// A random serial robot: mixed revolute/prismatic joints, offsets, off-axis COMs,
// products of inertia and a non-identity base.
inline RobotModel randomRobot(std::mt19937& rng, int n, DhConvention convention, bool withPrismatic = true) {
    std::srand(static_cast<unsigned>(rng()));  // Eigen's UnitRandom uses std::rand
    std::uniform_real_distribution<double> len(-0.6, 0.6), ang(-3.0, 3.0), mass(0.5, 5.0);
    RobotModel robot;
    robot.name = "random";
    robot.convention = convention;
    robot.base = Eigen::Translation3d(0.1, -0.2, 0.3) * Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized());
    robot.joints.resize(n);
    for (int i = 0; i < n; ++i) {
        Joint& j = robot.joints[i];
        j.dh.type = (withPrismatic && i % 3 == 2) ? JointType::Prismatic : JointType::Revolute;
        j.dh.a = len(rng);
        j.dh.alpha = ang(rng);
        j.dh.d = len(rng);
        j.dh.theta = ang(rng);
        j.link.mass = mass(rng);
        j.link.com = {len(rng), len(rng), len(rng)};
        j.link.inertia = randomInertia(rng);
    }
    return robot;
}

inline Eigen::VectorXd randomVector(std::mt19937& rng, int n, double range) {
    std::uniform_real_distribution<double> u(-range, range);
    Eigen::VectorXd v(n);
    for (int i = 0; i < n; ++i) v[i] = u(rng);
    return v;
}

// |a - b| <= tol * max(1, |b|), the absolute-or-relative comparison used throughout.
template <class A, class B>
double scaledError(const A& a, const B& b) {
    return (a - b).cwiseAbs().maxCoeff() / std::max(1.0, b.cwiseAbs().maxCoeff());
}

}  // namespace ll::test
