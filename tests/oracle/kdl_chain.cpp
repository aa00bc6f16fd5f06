#include "tests/oracle/kdl_chain.hpp"

#include <stdexcept>
#include <string>

#include <kdl/joint.hpp>
#include <kdl/segment.hpp>

namespace ll {

KDL::Vector toKdl(const Eigen::Vector3d& v) { return KDL::Vector(v.x(), v.y(), v.z()); }

KDL::Rotation toKdl(const Eigen::Matrix3d& R) {
    return KDL::Rotation(R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1), R(2, 2));
}

KDL::Frame toKdl(const Eigen::Isometry3d& T) {
    return KDL::Frame(toKdl(Eigen::Matrix3d(T.linear())), toKdl(Eigen::Vector3d(T.translation())));
}

KDL::RigidBodyInertia toKdl(const LinkInertia& link) {
    const Eigen::Matrix3d& I = link.inertia;
    // Tensor entries, same sign convention on both sides (see the header).
    const KDL::RotationalInertia Ic(I(0, 0), I(1, 1), I(2, 2), 0.5 * (I(0, 1) + I(1, 0)), 0.5 * (I(0, 2) + I(2, 0)),
                                    0.5 * (I(1, 2) + I(2, 1)));
    return KDL::RigidBodyInertia(link.mass, toKdl(link.com), Ic);  // Ic about the COM
}

Eigen::Vector3d toEigen(const KDL::Vector& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); }

Eigen::Matrix3d toEigen(const KDL::Rotation& R) {
    Eigen::Matrix3d M;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) M(r, c) = R(r, c);
    return M;
}

Eigen::Isometry3d toEigen(const KDL::Frame& F) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = toEigen(F.M);
    T.translation() = toEigen(F.p);
    return T;
}

namespace {

bool isIdentity(const Eigen::Isometry3d& T) { return T.matrix() == Eigen::Matrix4d::Identity(); }
bool isIdentity(const KDL::Frame& F) { return isIdentity(toEigen(F)); }  // exactly (KDL::Equal is strict)

// The motor's armature is KDL's joint inertia, which KDL adds to H(j,j) and inertia·q̈_j.
KDL::Joint jointOf(const Joint& joint) {
    return KDL::Joint(joint.dh.type == JointType::Revolute ? KDL::Joint::RotZ : KDL::Joint::TransZ, 1.0, 0.0, joint.motor.armature());
}

// Rot_x(α) Trans_x(a): the fixed head of a modified DH row.
KDL::Frame modifiedHead(const DhRow& row) { return KDL::Frame(KDL::Rotation::RotX(row.alpha), KDL::Vector(row.a, 0, 0)); }

// Rot_z(θ) Trans_z(d): the tail of a modified DH row after the joint.
KDL::Frame modifiedTail(const DhRow& row) { return KDL::Frame(KDL::Rotation::RotZ(row.theta), KDL::Vector(0, 0, row.d)); }

}  // namespace

KdlChain toKdlChain(const RobotModel& model, KdlChainLayout layout) {
    KdlChain out;
    const int n = model.dof();
    out.frameSegment.assign(n + 1, -1);
    out.frameCorrection.assign(n + 1, KDL::Frame::Identity());
    const KDL::Joint fixed(KDL::Joint::Fixed);
    int segments = 0;
    auto add = [&](const KDL::Segment& segment) {
        out.chain.addSegment(segment);
        return segments++;
    };

    if (layout == KdlChainLayout::Exact) {
        out.frameSegment[0] = add(KDL::Segment("base", fixed, toKdl(model.base)));
        for (int i = 0; i < n; ++i) {
            const Joint& joint = model.joints[i];
            const std::string name = "link" + std::to_string(i + 1);
            if (model.convention == DhConvention::Standard) {
                const DhRow& r = joint.dh;
                out.frameSegment[i + 1] =
                    add(KDL::Segment(name, jointOf(joint), KDL::Frame::DH(r.a, r.alpha, r.d, r.theta), toKdl(joint.link)));
            } else {
                add(KDL::Segment(name + "_head", fixed, modifiedHead(joint.dh)));
                out.frameSegment[i + 1] = add(KDL::Segment(name, jointOf(joint), modifiedTail(joint.dh), toKdl(joint.link)));
            }
        }
        return out;
    }

    // Compact.
    if (model.convention == DhConvention::Standard) {
        if (!isIdentity(model.base)) out.frameSegment[0] = add(KDL::Segment("base", fixed, toKdl(model.base)));
        for (int i = 0; i < n; ++i) {
            const Joint& joint = model.joints[i];
            const DhRow& r = joint.dh;
            out.frameSegment[i + 1] = add(KDL::Segment("link" + std::to_string(i + 1), jointOf(joint),
                                                       KDL::Frame::DH(r.a, r.alpha, r.d, r.theta), toKdl(joint.link)));
        }
        return out;
    }
    // Modified: segment i ends at frame i followed by row i+1's head.
    const KDL::Frame firstHead = n > 0 ? modifiedHead(model.joints[0].dh) : KDL::Frame::Identity();
    const KDL::Frame root = toKdl(model.base) * firstHead;
    if (!isIdentity(root)) out.frameSegment[0] = add(KDL::Segment("base", fixed, root));
    out.frameCorrection[0] = firstHead.Inverse();
    for (int i = 0; i < n; ++i) {
        const Joint& joint = model.joints[i];
        const KDL::Frame nextHead = i + 1 < n ? modifiedHead(model.joints[i + 1].dh) : KDL::Frame::Identity();
        const KDL::Frame toFrameI = nextHead.Inverse();  // frame i seen from the tip
        // KDL: operator*(T_a_b, I_b) = I_a. The link inertia is given in frame i.
        const KDL::RigidBodyInertia I = toFrameI * toKdl(joint.link);
        out.frameSegment[i + 1] = add(KDL::Segment("link" + std::to_string(i + 1), jointOf(joint), modifiedTail(joint.dh) * nextHead, I));
        out.frameCorrection[i + 1] = toFrameI;
    }
    return out;
}

// ---------------------------------------------------------------------------------------

KdlOracle::KdlOracle(const RobotModel& model, const Eigen::Vector3d& gravity, KdlChainLayout layout) {
    init(model, gravity, nullptr, layout);
}

KdlOracle::KdlOracle(const RobotModel& model, const Effects& effects, KdlChainLayout layout) {
    init(model, effects.gravity.value_or(Eigen::Vector3d::Zero()), &effects, layout);
}

KdlOracle::KdlOracle(KdlOracle&&) noexcept = default;
KdlOracle& KdlOracle::operator=(KdlOracle&&) noexcept = default;
KdlOracle::~KdlOracle() = default;

void KdlOracle::init(const RobotModel& model, const Eigen::Vector3d& gravity, const Effects* effects, KdlChainLayout layout) {
    n_ = model.dof();
    kdl_ = std::make_unique<KdlChain>(toKdlChain(model, layout));
    const KDL::Chain& chain = kdl_->chain;
    const KDL::Vector grav = toKdl(gravity);
    dyn_ = std::make_unique<KDL::ChainDynParam>(chain, grav);
    id_ = std::make_unique<KDL::ChainIdSolver_RNE>(chain, grav);
    fd_ = std::make_unique<KDL::ChainFdSolver_RNE>(chain, grav);
    fk_ = std::make_unique<KDL::ChainFkSolverPos_recursive>(chain);
    if (effects) springs_ = effects->springs;

    const unsigned nj = chain.getNrOfJoints();
    const unsigned ns = chain.getNrOfSegments();
    if (static_cast<int>(nj) != n_) throw std::logic_error("KdlOracle: KDL chain has the wrong number of joints");
    for (KDL::JntArray* a : {&q, &qd, &qdd, &tau, &c, &g, &tauOut, &qddOut}) a->resize(nj);
    H.resize(nj);
    fExt.assign(ns, KDL::Wrench::Zero());
    segmentFrames.assign(ns, KDL::Frame::Identity());
    B_.setZero(n_, n_);
    c_.setZero(n_);
    g_.setZero(n_);
    tau_.setZero(n_);
    qdd_.setZero(n_);
    springTau_.setZero(n_);
    T_.assign(n_ + 1, Eigen::Isometry3d::Identity());
}

void KdlOracle::check(int error, const char* what) {
    if (error < 0) throw std::runtime_error(std::string("KDL ") + what + " failed with error " + std::to_string(error));
}

void KdlOracle::addSprings(Eigen::VectorXd& out, const Eigen::VectorXd& qv) const {
    for (const JointSpring& s : springs_) out[s.joint] += s.stiffness * (qv[s.joint] - s.rest);
}

void KdlOracle::setState(const Eigen::VectorXd& qv, const Eigen::VectorXd& qdv) {
    q.data = qv;
    qd.data = qdv;
}
void KdlOracle::setAcceleration(const Eigen::VectorXd& qddv) { qdd.data = qddv; }
void KdlOracle::setTorque(const Eigen::VectorXd& tauv) { tau.data = tauv; }

int KdlOracle::kdlMassMatrix() { return dyn_->JntToMass(q, H); }
int KdlOracle::kdlCoriolis() { return dyn_->JntToCoriolis(q, qd, c); }
int KdlOracle::kdlGravity() { return dyn_->JntToGravity(q, g); }
int KdlOracle::kdlInverseDynamics() { return id_->CartToJnt(q, qd, qdd, fExt, tauOut); }
int KdlOracle::kdlForwardDynamics() { return fd_->CartToJnt(q, qd, tau, fExt, qddOut); }
int KdlOracle::kdlFramePoses() {
    if (segmentFrames.empty()) return 0;  // JntToCart refuses an empty chain
    return fk_->JntToCart(q, segmentFrames);
}

const Eigen::MatrixXd& KdlOracle::massMatrix(const Eigen::VectorXd& qv) {
    q.data = qv;
    check(kdlMassMatrix(), "ChainDynParam::JntToMass");
    B_ = H.data;
    return B_;
}

const Eigen::VectorXd& KdlOracle::coriolis(const Eigen::VectorXd& qv, const Eigen::VectorXd& qdv) {
    setState(qv, qdv);
    check(kdlCoriolis(), "ChainDynParam::JntToCoriolis");
    c_ = c.data;
    return c_;
}

const Eigen::VectorXd& KdlOracle::gravity(const Eigen::VectorXd& qv) {
    q.data = qv;
    check(kdlGravity(), "ChainDynParam::JntToGravity");
    g_ = g.data;
    addSprings(g_, qv);
    return g_;
}

const Eigen::VectorXd& KdlOracle::inverseDynamics(const Eigen::VectorXd& qv, const Eigen::VectorXd& qdv, const Eigen::VectorXd& qddv) {
    setState(qv, qdv);
    qdd.data = qddv;
    check(kdlInverseDynamics(), "ChainIdSolver_RNE::CartToJnt");
    tau_ = tauOut.data;
    addSprings(tau_, qv);
    return tau_;
}

const Eigen::VectorXd& KdlOracle::forwardDynamics(const Eigen::VectorXd& qv, const Eigen::VectorXd& qdv, const Eigen::VectorXd& tauv) {
    setState(qv, qdv);
    tau.data = tauv;
    if (!springs_.empty()) {
        springTau_.setZero();
        addSprings(springTau_, qv);
        tau.data -= springTau_;
    }
    check(kdlForwardDynamics(), "ChainFdSolver_RNE::CartToJnt");
    qdd_ = qddOut.data;
    return qdd_;
}

const std::vector<Eigen::Isometry3d>& KdlOracle::framePoses(const Eigen::VectorXd& qv) {
    q.data = qv;
    check(kdlFramePoses(), "ChainFkSolverPos_recursive::JntToCart");
    for (int i = 0; i <= n_; ++i) {
        const int s = kdl_->frameSegment[i];
        const KDL::Frame F = (s < 0 ? KDL::Frame::Identity() : segmentFrames[s]) * kdl_->frameCorrection[i];
        T_[i] = toEigen(F);
    }
    return T_;
}

}  // namespace ll
