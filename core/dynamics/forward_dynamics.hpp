#pragma once
// Forward dynamics q̈ = B(q)⁻¹ (Q − C(q, q̇) q̇ − g(q)), the pipeline named after its
// physics: kinematics → B (CRBA) → C q̇ + g (RNEA with q̈ = 0) → Cholesky solve.
// Never forms B⁻¹.
#include <stdexcept>
#include <string>

#include <Eigen/Core>

#include "core/model/effects.hpp"
#include "core/model/robot_data.hpp"
#include "core/model/robot_model.hpp"

namespace ll {

// B(q) is not positive definite: some joint moves no mass or inertia that the
// joints before it do not already move.
class SingularMassMatrix : public std::runtime_error {
public:
    SingularMassMatrix(int joint, const std::string& what) : std::runtime_error(what), joint_(joint) {}
    int joint() const { return joint_; }  // 0-based

private:
    int joint_;
};

// Factors data.B into data.B_llt; throws SingularMassMatrix naming the joint when B
// is not positive definite. Allocates nothing unless it throws.
void factorMassMatrix(RobotData& data);

// Q: (n) non-conservative generalized forces. Fills data.B, data.h, data.rhs, data.qdd;
// returns data.qdd. Throws SingularMassMatrix. Allocates nothing.
const Eigen::VectorXd& forwardDynamics(const RobotModel& model, RobotData& data, const Effects& effects, const Eigen::VectorXd& q,
                                       const Eigen::VectorXd& qd, const Eigen::VectorXd& Q);

// The first joint whose pivot in an unpivoted LDLᵀ of B is below relTol · max b_jj
// (its motion adds no inertia to the joints before it), or −1 if B is positive definite.
int firstSingularJoint(const Eigen::MatrixXd& B, double relTol = 1e-12);

}  // namespace ll
