#pragma once
// Scratch workspace for the algorithms on one RobotModel (Pinocchio's Model/Data
// split): sized once by the constructor, so evaluating kinematics and dynamics
// allocates nothing. Each field says what it holds, its size, and which stage fills it.
// All vectors are in the world frame (= DH base frame when the base is identity).
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/math/cholesky.hpp"
#include "core/math/spatial.hpp"
#include "core/model/robot_model.hpp"

namespace ll {

struct RobotData {
    explicit RobotData(const RobotModel& model);

    int n = 0;  // number of joints

    // --- constructor: constants of the model, so evaluations need no trigonometry of α ---
    std::vector<double> cosAlpha, sinAlpha;  // (n) cos α_i, sin α_i (α_{i-1} in modified DH)

    // --- forwardKinematics(model, data, q) ---
    std::vector<Eigen::Isometry3d> T_0i;     // (n+1) frame i in world; T_0i[0] = base
    std::vector<Eigen::Vector3d> p_ci;       // (n) COM of link i
    std::vector<Eigen::Matrix3d> I_li0;      // (n) I_li^0: inertia of link i about its COM, world axes: R_0i I_ci R_0iᵀ
    std::vector<Eigen::Vector3d> axis;       // (n) unit direction of joint i (z_{i-1} standard, z_i modified)
    std::vector<Eigen::Vector3d> axisPoint;  // (n) a point on that axis (o_{i-1} standard, o_i modified)
    std::vector<Vector6d> S;                 // (n) motion of joint i per unit q̇_i: [axis; axisPoint × axis] or [0; axis]
    std::vector<SpatialInertia> I;           // (n) spatial inertia of link i at the world origin

    // --- computeMassMatrix (CRBA) ---
    std::vector<SpatialInertia> I_composite;  // (n) composite inertia of links i..n
    Eigen::MatrixXd B;                        // (n x n) mass matrix, symmetric positive definite

    // --- computeCoriolisMatrix (Christoffel symbols) ---
    std::vector<Eigen::MatrixXd> dB_dq;  // (n) of (n x n): ∂B/∂q_k
    std::vector<Vector6d> crossS;        // (n*n) S_k × S_i at [k*n + i]
    std::vector<Vector6d> I_compositeS;  // (n*n) I_composite[b] S_j at [b*n + j]
    Eigen::MatrixXd C;                   // (n x n) Coriolis/centrifugal matrix

    // --- computePotentialGradient ---
    Eigen::VectorXd g;  // (n) ∂E_pot/∂q (gravity + springs)

    // --- inverseDynamics (RNEA) ---
    std::vector<Vector6d> V;  // (n) spatial velocity of link i
    std::vector<Vector6d> A;  // (n) spatial acceleration of link i (gravity as base acceleration)
    std::vector<Vector6d> F;  // (n) force transmitted across joint i
    Eigen::VectorXd tau;      // (n) joint torques/forces

    // --- forwardDynamics ---
    Eigen::VectorXd h;    // (n) C q̇ + g
    Eigen::VectorXd rhs;  // (n) Q − C q̇ − g
    Eigen::VectorXd qdd;  // (n) joint accelerations
    Cholesky B_llt;       // Cholesky factor of B
};

}  // namespace ll
