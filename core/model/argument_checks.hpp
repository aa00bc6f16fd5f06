#pragma once
// Size checks at the entry of the public core functions, in every build (not asserts):
// a worker still holding a state of 5 entries after a joint was added gets
// std::invalid_argument naming both sizes, never an out-of-bounds write. Each check is
// one comparison inline; the message is built only when it fails.
#include <Eigen/Core>

#include "core/model/effects.hpp"
#include "core/model/robot_data.hpp"
#include "core/model/robot_model.hpp"

namespace ll {

// Throw std::invalid_argument with the messages of the checks below.
[[noreturn]] void throwSizeMismatch(const char* function, const char* what, Eigen::Index size, Eigen::Index expected, const char* owner,
                                    const char* unit);
[[noreturn]] void throwDataMismatch(const char* function, int dataJoints, int modelJoints);
[[noreturn]] void throwJointIndex(const char* function, const char* what, int index, Eigen::Index joints);

// "<function>: <what> has <size> entries, <owner> has <expected> <unit>", e.g.
// "forwardKinematics: q has 5 entries, the robot has 6 joints".
inline void requireSize(const char* function, const char* what, Eigen::Index size, Eigen::Index expected, const char* owner = "the robot",
                        const char* unit = "joints") {
    if (size != expected) [[unlikely]]
        throwSizeMismatch(function, what, size, expected, owner, unit);
}

// data was made for this model, else "<function>: the RobotData was made for 5 joints,
// the robot has 6 joints".
inline void requireDataFor(const char* function, const RobotModel& model, const RobotData& data) {
    if (data.n != model.dof()) [[unlikely]]
        throwDataMismatch(function, data.n, model.dof());
}

// 0 <= index < joints, else "<function>: <what> is joint 7 (numbered from 1), the robot
// has 6 joints".
inline void requireJointIndex(const char* function, const char* what, int index, Eigen::Index joints) {
    if (index < 0 || index >= joints) [[unlikely]]
        throwJointIndex(function, what, index, joints);
}

// Every effect acts on one of `joints` joints (the effects of a scene whose robot lost
// a joint), else "<function>: effects.springs[0] is joint 6 (numbered from 1), the
// robot has 5 joints".
void requireEffectsFit(const char* function, const Effects& effects, Eigen::Index joints);

}  // namespace ll
