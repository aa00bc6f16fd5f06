#include "core/model/unit_slips.hpp"

#include <cmath>

#include <Eigen/Eigenvalues>

namespace ll {

namespace {

constexpr double kLongestLength = 10.0;   // [m] no arm's DH length is longer
constexpr double kHeaviestLink = 1000.0;  // [kg] no arm's link is heavier
constexpr double kReachFactor = 3.0;      // COM and radius of gyration: at most this × the reach
constexpr double kSmallestReach = 0.5;    // [m] the reach used for tiny or purely prismatic robots

// The reading of `value` [m] in a smaller unit that lands within `limit`, e.g.
// "typed in mm? 431.8 mm = 0.4318 m"; or a request to check it.
Message lengthSlip(double value, double limit) {
    const std::pair<const char*, double> units[] = {{"mm", 1e-3}, {"cm", 1e-2}, {"µm", 1e-6}};
    for (const auto& [unit, factor] : units)
        if (std::abs(value * factor) <= limit) return message(MessageId::TypedInLengthUnit, unit, value, value * factor);
    return MessageId::CheckLengthUnit;
}

}  // namespace

std::vector<Diagnostic> unitSlipWarnings(const RobotModel& model) {
    using enum MessageId;
    std::vector<Diagnostic> out;
    const auto warn = [&](std::string field, Message what, Message hint) {
        out.push_back({Severity::Warning, std::move(field), std::move(what), std::move(hint)});
    };
    double reach = 0.0;
    for (const Joint& joint : model.joints)
        for (double length : {joint.dh.a, joint.dh.d})
            if (std::abs(length) <= kLongestLength) reach += std::abs(length);
    const double size = kReachFactor * std::max(reach, kSmallestReach);
    const auto reachThen = [&](Message slip) { return message(RobotReachThen, reach, std::move(slip)); };

    for (int j = 0; j < model.dof(); ++j) {
        const Joint& joint = model.joints[j];
        for (const auto& [key, length] : {std::pair{"a", joint.dh.a}, std::pair{"d", joint.dh.d}})
            if (std::isfinite(length) && std::abs(length) > kLongestLength)
                warn(jointField(j, key), message(LongerThanAnyArm, length, kLongestLength), lengthSlip(length, kLongestLength));
        const Eigen::Vector3d& com = joint.link.com;
        if (com.allFinite() && com.norm() > size) {
            Eigen::Index k = 0;
            com.cwiseAbs().maxCoeff(&k);
            warn(jointField(j, "com[" + std::to_string(k) + "]"), message(ComFarOutside, com[k], com.norm()),
                 reachThen(lengthSlip(com[k], size)));
        }
        const double mass = joint.link.mass;
        if (std::isfinite(mass) && mass > kHeaviestLink)
            warn(jointField(j, "mass"), message(HeavierThanAnyLink, mass, kHeaviestLink), message(TypedInGrams, mass, mass * 1e-3));
        const Eigen::Matrix3d& I = joint.link.inertia;
        if (!(mass > 0) || !I.allFinite()) continue;
        const double largest = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I, Eigen::EigenvaluesOnly).eigenvalues()[2];
        const double gyration = std::sqrt(std::max(largest, 0.0) / mass);
        if (gyration > size) {
            const double grams = largest * 1e-9, kgmm = largest * 1e-6;
            warn(jointField(j, "inertia"), message(GyrationLargerThanRobot, gyration),
                 message(LargestMomentAndMass, largest, mass, reachThen(message(TypedInInertiaUnits, largest, grams, kgmm))));
        }
    }
    return out;
}

}  // namespace ll
