#pragma once
// KDL (orocos-kdl 1.5) as an independent numeric oracle: a RobotModel -> KDL::Chain
// converter and KdlOracle, which evaluates KDL's B(q), C(q,q̇)q̇, g(q), inverse and
// forward dynamics and frame poses into Eigen types. Used by tests/test_kdl_oracle.cpp
// and by `lagrangelab bench`, which times KDL beside our solvers.
//
// Mapping (verified against ll::forwardKinematics and the dynamics in the tests):
//   base      a fixed segment (Joint::Fixed) with f_tip = RobotModel::base, no inertia,
//             so the chain's root frame is the world frame in which gravity is given.
//   standard  A_i = Rot_z(θ+q) Trans_z(d) Trans_x(a) Rot_x(α) (revolute) or
//             Rot_z(θ) Trans_z(d+q) Trans_x(a) Rot_x(α) (prismatic):
//             one segment Segment(Joint(RotZ | TransZ), Frame::DH(a, α, d, θ), I_i).
//             KDL composes segment.pose(q) = joint.pose(q) * f_tip, and Rot_z(q) / Trans_z(q)
//             commute with Rot_z(θ) Trans_z(d), so pose(q) = A_i(q) exactly. The joint's
//             own offset is left at 0 (KDL's Segment stores joint.pose(0)⁻¹ f_tip, so an
//             offset would be cancelled at q = 0); θ and d live in f_tip.
//   modified  A_i = Rot_x(α_{i−1}) Trans_x(a_{i−1}) Rot_z(θ+q) Trans_z(d): the joint sits in
//             the middle, but KDL's joint sits at the segment root, so
//             KdlChainLayout::Exact: a fixed segment Frame(Rot_x(α), (a,0,0)) with no
//                inertia, then Segment(Joint(RotZ | TransZ), Frame(Rot_z(θ), (0,0,d)), I_i).
//             KdlChainLayout::Compact: the fixed part of row i+1 is folded into segment i's
//                f_tip = Rot_z(θ_i) Trans_z(d_i) Rot_x(α_{i+1}) Trans_x(a_{i+1}) (and row 1's
//                into the base segment), the inertia re-expressed in that tip frame; n
//                segments (+1 base segment unless it is the identity), as a KDL user
//                would write it. Use it for timing; Exact keeps every number untouched.
//   inertia   link i lives in DH frame i, which is the tip frame of its KDL segment (Exact;
//             standard in both layouts): RigidBodyInertia(m, com, RotationalInertia about
//             the COM). KDL's RotationalInertia(Ixx, Iyy, Izz, Ixy, Ixz, Iyz) stores the
//             tensor entries as given (data = [Ixx Ixy Ixz; Ixy Iyy Iyz; Ixz Iyz Izz]), the
//             same convention as LinkInertia::inertia; the off-diagonals are taken as the
//             mean of the two mirrored entries.
//   armature  a joint's motor armature Jm G² is KDL's joint inertia (Joint(type, 1, 0,
//             inertia)), which KDL 1.5 adds to H(j,j) (ChainDynParam) and inertia·q̈_j
//             (ChainIdSolver_RNE, ChainFdSolver_RNE).
//   springs   KDL has none: KdlOracle(model, effects) adds K(q − rest) to gravity() and
//             inverseDynamics() and subtracts it from τ before KDL's forward dynamics.
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <kdl/chain.hpp>
#include <kdl/chaindynparam.hpp>
#include <kdl/chainfdsolver_recursive_newton_euler.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainidsolver_recursive_newton_euler.hpp>
#include <kdl/frames.hpp>
#include <kdl/jntarray.hpp>
#include <kdl/jntspaceinertiamatrix.hpp>
#include <kdl/rigidbodyinertia.hpp>

#include "core/model/effects.hpp"
#include "core/model/link_inertia.hpp"
#include "core/model/robot_model.hpp"

namespace ll {

enum class KdlChainLayout {
    Exact,    // fixed segments for the base and for modified DH's Rot_x Trans_x; inertias as given
    Compact,  // fixed transforms folded into neighbouring segments (fewest segments, for timing)
};

// A KDL chain plus where each DH frame sits on it.
struct KdlChain {
    KDL::Chain chain;
    // DH frame i (0..n) in the world = (pose of the tip of segment frameSegment[i], or the
    // identity if -1) * frameCorrection[i]. The correction is the identity except for
    // modified DH in the Compact layout.
    std::vector<int> frameSegment;
    std::vector<KDL::Frame> frameCorrection;
};

KDL::Vector toKdl(const Eigen::Vector3d& v);
KDL::Rotation toKdl(const Eigen::Matrix3d& R);
KDL::Frame toKdl(const Eigen::Isometry3d& T);
KDL::RigidBodyInertia toKdl(const LinkInertia& link);  // about the link frame's origin
Eigen::Vector3d toEigen(const KDL::Vector& v);
Eigen::Matrix3d toEigen(const KDL::Rotation& R);
Eigen::Isometry3d toEigen(const KDL::Frame& F);

KdlChain toKdlChain(const RobotModel& model, KdlChainLayout layout = KdlChainLayout::Exact);

// KDL's solvers with their inputs and outputs, built once per model. Evaluating
// allocates nothing (the chain and solvers live on the heap, so a KdlOracle can be moved).
// The Eigen-facing calls copy the input into the JntArrays, call KDL, copy the result
// out and return a reference to an internal buffer, valid until the next call.
// They throw std::runtime_error if a KDL solver returns an error.
class KdlOracle {
public:
    KdlOracle(const RobotModel& model, const Eigen::Vector3d& gravity, KdlChainLayout layout = KdlChainLayout::Exact);
    // Gravity from effects.gravity (zero if absent) and the springs; friction and
    // external torques are generalized forces Q, which the caller passes as τ.
    KdlOracle(const RobotModel& model, const Effects& effects, KdlChainLayout layout = KdlChainLayout::Exact);

    KdlOracle(KdlOracle&&) noexcept;
    KdlOracle& operator=(KdlOracle&&) noexcept;
    ~KdlOracle();

    int dof() const { return n_; }
    const KDL::Chain& chain() const { return kdl_->chain; }
    const KdlChain& kdlChain() const { return *kdl_; }

    // --- Eigen in, Eigen out ---
    const Eigen::MatrixXd& massMatrix(const Eigen::VectorXd& q);                           // B(q)
    const Eigen::VectorXd& coriolis(const Eigen::VectorXd& q, const Eigen::VectorXd& qd);  // C(q,q̇) q̇
    const Eigen::VectorXd& gravity(const Eigen::VectorXd& q);                              // g(q) (+ springs)
    const Eigen::VectorXd& inverseDynamics(const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
                                           const Eigen::VectorXd& qdd);  // τ (+ springs)
    const Eigen::VectorXd& forwardDynamics(const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
                                           const Eigen::VectorXd& tau);  // q̈
    // T_0i for i = 0..n (n+1 poses, world frame), as ll::RobotData::T_0i.
    const std::vector<Eigen::Isometry3d>& framePoses(const Eigen::VectorXd& q);

    // --- raw KDL, for timing: set the inputs once, then call the solver alone ---
    void setState(const Eigen::VectorXd& q, const Eigen::VectorXd& qd);
    void setAcceleration(const Eigen::VectorXd& qdd);
    void setTorque(const Eigen::VectorXd& tau);  // used as is (no spring correction)
    int kdlMassMatrix();                         // dynParam.JntToMass(q, H)           -> H
    int kdlCoriolis();                           // dynParam.JntToCoriolis(q, qd, c)   -> c
    int kdlGravity();                            // dynParam.JntToGravity(q, g)        -> g
    int kdlInverseDynamics();                    // idSolver.CartToJnt(q, qd, qdd, 0, tau_out)  -> tauOut
    int kdlForwardDynamics();                    // fdSolver.CartToJnt(q, qd, tau, 0, qdd_out)  -> qddOut
    int kdlFramePoses();                         // fkSolver.JntToCart(q, segmentFrames) -> segmentFrames

    KDL::ChainDynParam& dynParam() { return *dyn_; }
    KDL::ChainIdSolver_RNE& idSolver() { return *id_; }
    KDL::ChainFdSolver_RNE& fdSolver() { return *fd_; }
    KDL::ChainFkSolverPos_recursive& fkSolver() { return *fk_; }

    KDL::JntArray q, qd, qdd, tau;  // inputs
    KDL::JntSpaceInertiaMatrix H;   // outputs
    KDL::JntArray c, g, tauOut, qddOut;
    KDL::Wrenches fExt;  // zero external wrenches, one per segment
    std::vector<KDL::Frame> segmentFrames;

private:
    void init(const RobotModel& model, const Eigen::Vector3d& gravity, const Effects* effects, KdlChainLayout layout);
    void addSprings(Eigen::VectorXd& out, const Eigen::VectorXd& qv) const;
    static void check(int error, const char* what);

    int n_ = 0;
    std::unique_ptr<KdlChain> kdl_;  // the solvers hold references to kdl_->chain
    std::unique_ptr<KDL::ChainDynParam> dyn_;
    std::unique_ptr<KDL::ChainIdSolver_RNE> id_;
    std::unique_ptr<KDL::ChainFdSolver_RNE> fd_;
    std::unique_ptr<KDL::ChainFkSolverPos_recursive> fk_;
    std::vector<JointSpring> springs_;
    Eigen::MatrixXd B_;
    Eigen::VectorXd c_, g_, tau_, qdd_, springTau_;
    std::vector<Eigen::Isometry3d> T_;
};

}  // namespace ll
