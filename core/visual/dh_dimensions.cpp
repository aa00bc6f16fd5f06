#include "core/visual/dh_dimensions.hpp"

#include <cmath>
#include <cstdio>

namespace ll {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string labelOf(const RobotModel& robot, int joint, const ElementaryMotion& m) {
    const bool standard = robot.convention == DhConvention::Standard;
    const int row = joint + 1, before = standard ? row : row - 1;  // modified: a_{i-1}, α_{i-1}
    char text[64];
    switch (m.parameter) {
        case DhParameter::Theta: std::snprintf(text, sizeof text, "θ%d = %.1f°", row, m.amount * 180 / kPi); break;
        case DhParameter::Alpha: std::snprintf(text, sizeof text, "α%d = %.1f°", before, m.amount * 180 / kPi); break;
        case DhParameter::D: std::snprintf(text, sizeof text, "d%d = %.4g m", row, m.amount); break;
        case DhParameter::A: std::snprintf(text, sizeof text, "a%d = %.4g m", before, m.amount); break;
    }
    return text;
}

}  // namespace

std::vector<DhDimension> dhDimensions(const RobotModel& robot, const RobotData& data, const Eigen::VectorXd& q, double arcRadius) {
    std::vector<DhDimension> out;
    for (int j = 0; j < robot.dof(); ++j) {
        Eigen::Isometry3d frame = data.T_0i[static_cast<std::size_t>(j)];
        for (const ElementaryMotion& m : elementaryMotions(robot, j, q[j])) {
            const Eigen::Isometry3d after = frame * m.transform();
            if (std::abs(m.amount) > 1e-9) {
                DhDimension d;
                d.joint = j;
                d.parameter = m.parameter;
                d.angle = m.rotates();
                d.value = m.amount;
                d.label = labelOf(robot, j, m);
                if (!d.angle) {
                    d.points = {frame.translation(), after.translation()};
                    d.labelAt = (frame.translation() + after.translation()) / 2;
                } else {
                    // About z (θ) the x axis turns; about x (α) the z axis does.
                    const bool aboutZ = m.kind == ElementaryMotion::Kind::RotZ;
                    const Eigen::Vector3d axis = frame.linear().col(aboutZ ? 2 : 0);
                    const Eigen::Vector3d from = frame.linear().col(aboutZ ? 0 : 2);
                    const int steps = std::max(4, static_cast<int>(std::ceil(std::abs(m.amount) / (kPi / 24))));
                    for (int s = 0; s <= steps; ++s) {
                        const double phi = m.amount * s / steps;
                        d.points.push_back(frame.translation() + arcRadius * (Eigen::AngleAxisd(phi, axis) * from));
                    }
                    d.labelAt = frame.translation() + 1.25 * arcRadius * (Eigen::AngleAxisd(m.amount / 2, axis) * from);
                }
                out.push_back(std::move(d));
            }
            frame = after;
        }
    }
    return out;
}

}  // namespace ll
