#include "core/model/unit_slips.hpp"

#include <cmath>
#include <sstream>

#include <Eigen/Eigenvalues>

namespace ll {

namespace {

constexpr double kLongestLength = 10.0;   // [m] no arm's DH length is longer
constexpr double kHeaviestLink = 1000.0;  // [kg] no arm's link is heavier
constexpr double kReachFactor = 3.0;      // COM and radius of gyration: at most this × the reach
constexpr double kSmallestReach = 0.5;    // [m] the reach used for tiny or purely prismatic robots

std::string fmt(double v) {
    std::ostringstream s;
    s.precision(6);
    s << v;
    return s.str();
}

// The reading of `value` [m] in a smaller unit that lands within `limit`, e.g.
// " in mm? 431.8 mm = 0.4318 m"; or a request to check it.
std::string lengthSlip(double value, double limit) {
    const std::pair<const char*, double> units[] = {{"mm", 1e-3}, {"cm", 1e-2}, {"µm", 1e-6}};
    for (const auto& [unit, factor] : units)
        if (std::abs(value * factor) <= limit)
            return "typed in " + std::string(unit) + "? " + fmt(value) + " " + unit + " = " + fmt(value * factor) + " m";
    return "check its unit (m) and its digits";
}

}  // namespace

std::vector<Diagnostic> unitSlipWarnings(const RobotModel& model) {
    std::vector<Diagnostic> out;
    const auto warn = [&](std::string field, std::string message, std::string hint) {
        out.push_back({Severity::Warning, std::move(field), std::move(message), std::move(hint)});
    };
    double reach = 0.0;
    for (const Joint& joint : model.joints)
        for (double length : {joint.dh.a, joint.dh.d})
            if (std::abs(length) <= kLongestLength) reach += std::abs(length);
    const double size = kReachFactor * std::max(reach, kSmallestReach);
    const std::string reachText = "the robot's reach is about " + fmt(reach) + " m (sum of |a| and |d|)";

    for (int j = 0; j < model.dof(); ++j) {
        const Joint& joint = model.joints[j];
        for (const auto& [key, length] : {std::pair{"a", joint.dh.a}, std::pair{"d", joint.dh.d}})
            if (std::isfinite(length) && std::abs(length) > kLongestLength)
                warn(jointField(j, key), fmt(length) + " m is longer than any arm (over " + fmt(kLongestLength) + " m)",
                     lengthSlip(length, kLongestLength));
        const Eigen::Vector3d& com = joint.link.com;
        if (com.allFinite() && com.norm() > size) {
            Eigen::Index k = 0;
            com.cwiseAbs().maxCoeff(&k);
            warn(jointField(j, "com[" + std::to_string(k) + "]"),
                 fmt(com[k]) + " m puts the centre of mass " + fmt(com.norm()) + " m from its frame, far outside the robot",
                 reachText + ": " + lengthSlip(com[k], size));
        }
        const double mass = joint.link.mass;
        if (std::isfinite(mass) && mass > kHeaviestLink)
            warn(jointField(j, "mass"), fmt(mass) + " kg is heavier than any arm's link (over " + fmt(kHeaviestLink) + " kg)",
                 "typed in g? " + fmt(mass) + " g = " + fmt(mass * 1e-3) + " kg");
        const Eigen::Matrix3d& I = joint.link.inertia;
        if (!(mass > 0) || !I.allFinite()) continue;
        const double largest = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I, Eigen::EigenvaluesOnly).eigenvalues()[2];
        const double gyration = std::sqrt(std::max(largest, 0.0) / mass);
        if (gyration > size) {
            const double grams = largest * 1e-9, kgmm = largest * 1e-6;
            warn(jointField(j, "inertia"),
                 "radius of gyration sqrt(I/m) = " + fmt(gyration) + " m is larger than the whole robot",
                 "largest principal moment " + fmt(largest) + " kg m², mass " + fmt(mass) + " kg; " + reachText +
                     ": typed in g mm² or kg mm²? " + fmt(largest) + " g mm² = " + fmt(grams) + " kg m², " + fmt(largest) +
                     " kg mm² = " + fmt(kgmm) + " kg m²");
        }
    }
    return out;
}

}  // namespace ll
