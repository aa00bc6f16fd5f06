#pragma once
// Why B(q) cannot be factored, told apart so that a message can say what to change:
//  - MovesNothing: joint j truly moves nothing the joints before it do not already
//    move (the links beyond it have no mass off its axis and no inertia about it, or
//    it only repeats an earlier axis). B is singular in exact arithmetic.
//  - IllConditioned: joint j does move inertia of its own, but B spans so many
//    orders of magnitude that in double precision its share is lost beside the
//    largest entries (a unit slip such as a COM in mm, or light distal links beside
//    heavy proximal ones; a motor's armature on the light joints is the cure).
#include <Eigen/Core>

#include "core/model/robot_data.hpp"

namespace ll {

struct MassMatrixDefect {
    enum class Kind { None, MovesNothing, IllConditioned };
    Kind kind = Kind::None;
    int joint = -1;          // 0-based: the first joint whose LDLᵀ pivot fails (firstSingularJoint)
    double condition = 0.0;  // λ_max / λ_min of B; infinite when λ_min <= 0
    double diagonal = 0.0;   // b_jj
    double pivot = 0.0;      // b_jj minus what the joints before it already account for
    double largest = 0.0;    // max_i b_ii, the scale the pivot is judged against
};

// Requires computeMassMatrix (reads data.B, data.I_composite and data.S). `relTol` as in
// firstSingularJoint. Allocates.
MassMatrixDefect diagnoseMassMatrix(const RobotData& data, double relTol = 1e-12);

}  // namespace ll
