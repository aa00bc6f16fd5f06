#include "core/model/argument_checks.hpp"

#include <stdexcept>
#include <string>

namespace ll {

void throwSizeMismatch(const char* function, const char* what, Eigen::Index size, Eigen::Index expected, const char* owner,
                       const char* unit) {
    throw std::invalid_argument(std::string(function) + ": " + what + " has " + std::to_string(size) +
                                (size == 1 ? " entry, " : " entries, ") + owner + " has " + std::to_string(expected) + " " + unit);
}

void throwDataMismatch(const char* function, int dataJoints, int modelJoints) {
    throw std::invalid_argument(std::string(function) + ": the RobotData was made for " + std::to_string(dataJoints) +
                                " joints, the robot has " + std::to_string(modelJoints) + " joints");
}

void throwJointIndex(const char* function, const char* what, int index, Eigen::Index joints) {
    throw std::invalid_argument(std::string(function) + ": " + what + " is joint " + std::to_string(index + 1) +
                                " (numbered from 1), the robot has " + std::to_string(joints) + " joints");
}

namespace {
template <class Entries>
void requireFit(const char* function, const char* kind, const Entries& entries, Eigen::Index joints) {
    for (std::size_t k = 0; k < entries.size(); ++k)
        if (const int joint = entries[k].joint; joint < 0 || joint >= joints) [[unlikely]] {
            const std::string what = std::string("effects.") + kind + "[" + std::to_string(k) + "]";
            throwJointIndex(function, what.c_str(), joint, joints);
        }
}
}  // namespace

void requireEffectsFit(const char* function, const Effects& effects, Eigen::Index joints) {
    requireFit(function, "springs", effects.springs, joints);
    requireFit(function, "viscous", effects.viscous, joints);
    requireFit(function, "coulomb", effects.coulomb, joints);
    requireFit(function, "torques", effects.torques, joints);
}

}  // namespace ll
