#pragma once
// One row of a Denavit–Hartenberg table and the convention that reads it.

namespace ll {

// standard: Spong/Siciliano, A_i = Rot_z(θ_i) Trans_z(d_i) Trans_x(a_i) Rot_x(α_i);
//           joint i moves about/along z_{i-1}.
// modified: Craig, A_i = Rot_x(α_{i-1}) Trans_x(a_{i-1}) Rot_z(θ_i) Trans_z(d_i);
//           joint i moves about/along z_i. Row i then holds a_{i-1}, α_{i-1}, d_i, θ_i.
enum class DhConvention { Standard, Modified };

enum class JointType { Revolute, Prismatic };

// The joint variable q_i adds to theta (revolute) or to d (prismatic); the stored
// theta and d are the constant offsets.
struct DhRow {
    JointType type = JointType::Revolute;
    double a = 0.0;
    double alpha = 0.0;
    double d = 0.0;
    double theta = 0.0;
};

const char* toString(DhConvention convention);
const char* toString(JointType type);

}  // namespace ll
