// Our dynamics against orocos-kdl, an independent implementation (KDL's own RNE,
// composite-inertia mass matrix and LDLᵀ forward dynamics in body coordinates):
// B(q), C(q,q̇)q̇, g(q), RNEA τ, forward dynamics q̈ and the frame poses T_0i, at
// 200 random states per robot, for textbook robots (PUMA 560, Stanford arm, from
// C++ and from examples/*.json) and random robots read in both DH conventions,
// each through both KDL chain layouts (see tests/oracle/kdl_chain.hpp).
//
// Tolerance: err(a, b) = max_k |a_k − b_k| / max(1, max_k |b_k|) (b = KDL), i.e.
// absolute below unit magnitude and relative to the largest entry above it:
//   B, C q̇, g, τ, T_0i:  1e-9   (both sides are a few dozen flops per entry from
//                                  the same doubles; observed errors are ~1e-14)
//   q̈ (forward dynamics): 1e-8 — q̈ = B⁻¹(τ − h) amplifies the rounding of B and h
//                                  by up to cond(B) (≈1e3–1e5 for these robots:
//                                  wrist inertias of 1e-4 kg m² beside 3 kg m²), and
//                                  KDL factors B by an unpivoted LDLᵀ, we by LLᵀ.
// The test prints the largest error observed per quantity and robot.
#include "test_registry.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <random>
#include <string>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "core/dynamics/coriolis.hpp"
#include "core/dynamics/forward_dynamics.hpp"
#include "core/dynamics/potential_gradient.hpp"
#include "core/dynamics/inverse_dynamics.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/io/scene_file.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/model/robot_data.hpp"
#include "tests/oracle/kdl_chain.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_kdl_oracle {

using namespace ll;

namespace {

constexpr double kTol = 1e-9;
constexpr double kTolFd = 1e-8;
constexpr int kSamples = 200;
constexpr double kPi = 3.14159265358979323846;

// |a - b| <= err * max(1, |b|), elementwise with the largest entries.
template <class A, class B>
double scaledError(const A& a, const B& b) {
    return (a - b).cwiseAbs().maxCoeff() / std::max(1.0, b.cwiseAbs().maxCoeff());
}

// ---- robots --------------------------------------------------------------------

Joint makeJoint(JointType type, double a, double alpha, double d, double theta, double m, Eigen::Vector3d com,
                Eigen::Vector3d diagInertia) {
    Joint j;
    j.dh = {type, a, alpha, d, theta};
    j.link.mass = m;
    j.link.com = com;
    j.link.inertia = diagInertia.asDiagonal();
    return j;
}

// PUMA 560, standard DH, Corke's mdl_puma560 dynamic parameters (rigid body only).
RobotModel puma560() {
    const auto R = JointType::Revolute;
    RobotModel r;
    r.name = "PUMA 560 (C++)";
    r.joints = {
        makeJoint(R, 0, kPi / 2, 0, 0, 0, {0, 0, 0}, {0, 0.35, 0}),
        makeJoint(R, 0.4318, 0, 0, 0, 17.4, {-0.3638, 0.006, 0.2275}, {0.13, 0.524, 0.539}),
        makeJoint(R, 0.0203, -kPi / 2, 0.15005, 0, 4.8, {-0.0203, -0.0141, 0.070}, {0.066, 0.086, 0.0125}),
        makeJoint(R, 0, kPi / 2, 0.4318, 0, 0.82, {0, 0.019, 0}, {1.8e-3, 1.3e-3, 1.8e-3}),
        makeJoint(R, 0, -kPi / 2, 0, 0, 0.34, {0, 0, 0}, {0.3e-3, 0.4e-3, 0.3e-3}),
        makeJoint(R, 0, 0, 0, 0, 0.09, {0, 0, 0.032}, {0.15e-3, 0.15e-3, 0.04e-3}),
    };
    return r;
}

// Stanford arm, standard DH, after Corke's mdl_stanford (prismatic joint 3).
RobotModel stanfordArm() {
    const auto R = JointType::Revolute;
    const auto P = JointType::Prismatic;
    RobotModel r;
    r.name = "Stanford arm (C++)";
    r.joints = {
        makeJoint(R, 0, -kPi / 2, 0.412, 0, 9.29, {0, 0.0175, -0.1105}, {0.276, 0.255, 0.071}),
        makeJoint(R, 0, kPi / 2, 0.154, 0, 5.01, {0, -0.1054, 0}, {0.108, 0.018, 0.100}),
        makeJoint(P, 0.0203, 0, 0, -kPi / 2, 4.25, {0, 0, -0.6447}, {2.51, 2.51, 0.006}),
        makeJoint(R, 0, -kPi / 2, 0, 0, 1.08, {0, 0.092, -0.054}, {0.002, 0.001, 0.001}),
        makeJoint(R, 0, kPi / 2, 0, 0, 0.630, {0, 0, 0.0566}, {0.003, 0.0004, 0.003}),
        makeJoint(R, 0, 0, 0, 0, 0.51, {0, 0, 0.1554}, {0.013, 0.013, 0.0003}),
    };
    return r;
}

double uniform(std::mt19937_64& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
// A nonzero number with |x| in [lo, hi] and a random sign.
double signedUniform(std::mt19937_64& rng, double lo, double hi) { return (uniform(rng, 0, 1) < 0.5 ? -1.0 : 1.0) * uniform(rng, lo, hi); }

Eigen::Matrix3d randomRotation(std::mt19937_64& rng) {
    Eigen::Quaterniond quat(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    quat.normalize();
    return quat.toRotationMatrix();
}

// R diag(λ) Rᵀ with λ satisfying the triangle inequality; exactly symmetric.
Eigen::Matrix3d randomInertia(std::mt19937_64& rng) {
    Eigen::Vector3d lambda;
    do {
        lambda << uniform(rng, 0.01, 0.4), uniform(rng, 0.01, 0.4), uniform(rng, 0.01, 0.4);
    } while (lambda[0] + lambda[1] <= 1.05 * lambda[2] || lambda[1] + lambda[2] <= 1.05 * lambda[0] ||
             lambda[0] + lambda[2] <= 1.05 * lambda[1]);
    const Eigen::Matrix3d R = randomRotation(rng);
    const Eigen::Matrix3d I = R * lambda.asDiagonal() * R.transpose();
    return 0.5 * (I + I.transpose());
}

// Random robot: pattern "RRP..." gives the joint types. The same seed gives the same
// numbers whatever the convention, so standard and modified read one table two ways.
RobotModel randomRobot(std::uint64_t seed, const std::string& pattern, DhConvention convention) {
    std::mt19937_64 rng(seed);
    RobotModel r;
    r.name = "random " + pattern;
    r.convention = convention;
    r.base.linear() = randomRotation(rng);
    r.base.translation() = Eigen::Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    for (char c : pattern) {
        Joint j;
        j.dh.type = c == 'P' ? JointType::Prismatic : JointType::Revolute;
        j.dh.a = signedUniform(rng, 0.05, 0.5);
        j.dh.alpha = signedUniform(rng, 0.2, 2.9);
        j.dh.d = signedUniform(rng, 0.05, 0.5);
        j.dh.theta = signedUniform(rng, 0.1, 3.0);
        j.link.mass = uniform(rng, 0.5, 5.0);
        j.link.com = Eigen::Vector3d(signedUniform(rng, 0.02, 0.3), signedUniform(rng, 0.02, 0.3), signedUniform(rng, 0.02, 0.3));
        j.link.inertia = randomInertia(rng);
        r.joints.push_back(j);
    }
    return r;
}

const Eigen::Vector3d kTiltedGravity(1.2, -0.7, -9.5);
const Eigen::Vector3d kEarthGravity(0, 0, -9.81);

struct Case {
    RobotModel model;
    Effects effects;
    QString skip;  // non-empty: QSKIP with this message
};

Effects gravityOnly(const Eigen::Vector3d& g) {
    Effects e;
    e.gravity = g;
    return e;
}

Case fromFile(const std::string& file) {
    const std::string path = std::string(LL_EXAMPLES_DIR) + "/" + file;
    if (!std::filesystem::exists(path)) return {{}, {}, QString("%1 is absent").arg(QString::fromStdString(path))};
    LoadedScene loaded = loadScene(path);
    Case c{loaded.scene.robot, loaded.scene.effects, {}};
    if (!c.effects.gravity) c.effects.gravity = kEarthGravity;  // compare g(q) with something in it
    return c;
}

// name -> robot. "std"/"mod" pick the convention of the random robots.
Case makeCase(const QString& name) {
    const std::string n = name.toStdString();
    if (n == "puma560") return {puma560(), gravityOnly(kEarthGravity), {}};
    if (n == "stanford") return {stanfordArm(), gravityOnly(kEarthGravity), {}};
    if (n == "puma560.json") return fromFile("puma560.json");
    if (n == "puma560_modified.json") return fromFile("puma560_modified.json");
    if (n == "stanford_arm.json") return fromFile("stanford_arm.json");
    const DhConvention conv = name.endsWith("mod") ? DhConvention::Modified : DhConvention::Standard;
    if (name.startsWith("random7")) return {randomRobot(7, "RRPRPRR", conv), gravityOnly(kTiltedGravity), {}};
    if (name.startsWith("random6")) return {randomRobot(6, "PRRPRR", conv), gravityOnly(kTiltedGravity), {}};
    if (name.startsWith("revolute6")) return {randomRobot(61, "RRRRRR", conv), gravityOnly(kTiltedGravity), {}};
    if (name.startsWith("prismatic1")) return {randomRobot(1, "P", conv), gravityOnly(kTiltedGravity), {}};
    if (name.startsWith("revolute1")) return {randomRobot(11, "R", conv), gravityOnly(kTiltedGravity), {}};
    if (name.startsWith("nobase7")) {  // Compact layout then needs no base segment
        Case c{randomRobot(8, "RPRRPRR", conv), gravityOnly(kTiltedGravity), {}};
        c.model.base = Eigen::Isometry3d::Identity();
        c.model.joints[0].dh.a = c.model.joints[0].dh.alpha = 0;
        return c;
    }
    if (name.startsWith("springs7")) {
        Case c{randomRobot(7, "RRPRPRR", conv), gravityOnly(kTiltedGravity), {}};
        c.effects.springs = {{0, 12.0, 0.3}, {2, 150.0, -0.1}, {5, 4.0, 1.0}};
        return c;
    }
    qFatal("unknown robot %s", qPrintable(name));
    return {};
}

const QStringList kRobots = {"puma560",       "stanford",       "puma560.json",   "puma560_modified.json", "stanford_arm.json",
                             "random7 std",   "random7 mod",    "random6 std",    "random6 mod",           "revolute6 std",
                             "revolute6 mod", "prismatic1 std", "prismatic1 mod", "revolute1 std",         "revolute1 mod",
                             "nobase7 std",   "nobase7 mod",    "springs7 std",   "springs7 mod"};

struct State {
    Eigen::VectorXd q, qd, qdd;
};

State randomState(std::mt19937_64& rng, const RobotModel& model) {
    const int n = model.dof();
    State s{Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::VectorXd(n)};
    for (int i = 0; i < n; ++i) {
        const bool revolute = model.joints[i].dh.type == JointType::Revolute;
        s.q[i] = revolute ? uniform(rng, -kPi, kPi) : uniform(rng, -0.5, 0.5);
        s.qd[i] = uniform(rng, -3, 3);
        s.qdd[i] = uniform(rng, -5, 5);
    }
    return s;
}

double maxFrameError(const RobotData& data, const std::vector<Eigen::Isometry3d>& kdl) {
    double worst = 0;
    for (std::size_t i = 0; i < kdl.size(); ++i) worst = std::max(worst, scaledError(data.T_0i[i].matrix(), kdl[i].matrix()));
    return worst;
}

}  // namespace

class TestKdlOracle : public QObject {
    Q_OBJECT
private slots:
    // KDL's inertia conventions as the header claims: RotationalInertia stores tensor
    // entries as given; RigidBodyInertia(m, c, Ic) takes Ic about the COM and keeps the
    // inertia about the frame origin, Ic + m(|c|²1 − c cᵀ).
    void inertiaConventions() {
        std::mt19937_64 rng(5);
        LinkInertia link;
        link.mass = 2.5;
        link.com = {0.1, -0.2, 0.3};
        link.inertia = randomInertia(rng);
        const KDL::RigidBodyInertia I = toKdl(link);
        QCOMPARE(I.getMass(), link.mass);
        QVERIFY(scaledError(toEigen(I.getCOG()), link.com) < 1e-15);
        Eigen::Matrix3d Io;
        const KDL::RotationalInertia Ik = I.getRotationalInertia();
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) Io(r, c) = Ik.data[3 * r + c];
        const Eigen::Vector3d& c = link.com;
        const Eigen::Matrix3d expected = link.inertia + link.mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
        QVERIFY2(scaledError(Io, expected) < 1e-14, qPrintable(QString::number(scaledError(Io, expected))));
        // Ic·ω through KDL equals the tensor times ω (so the off-diagonal signs agree).
        const KDL::RotationalInertia Ic(link.inertia(0, 0), link.inertia(1, 1), link.inertia(2, 2), link.inertia(0, 1), link.inertia(0, 2),
                                        link.inertia(1, 2));
        const Eigen::Vector3d w(0.3, -1.1, 0.7);
        QVERIFY(scaledError(toEigen(Ic * toKdl(w)), Eigen::Vector3d(link.inertia * w)) < 1e-15);
    }

    // Frame::DH is the standard A_i (θ, d including the joint variable).
    void frameDhIsStandardDh() {
        RobotModel r = randomRobot(3, "RP", DhConvention::Standard);
        for (int i = 0; i < 2; ++i) {
            const DhRow& row = r.joints[i].dh;
            const double qi = 0.37;
            const bool rev = row.type == JointType::Revolute;
            const KDL::Frame F = KDL::Frame::DH(row.a, row.alpha, row.d + (rev ? 0 : qi), row.theta + (rev ? qi : 0));
            QVERIFY(scaledError(toEigen(F).matrix(), linkTransform(r, i, qi).matrix()) < 1e-15);
        }
    }

    void agreesWithKdl_data() {
        QTest::addColumn<QString>("robot");
        QTest::addColumn<int>("layout");
        for (const QString& robot : kRobots) {
            QTest::newRow(qPrintable(robot + " exact")) << robot << int(KdlChainLayout::Exact);
            QTest::newRow(qPrintable(robot + " compact")) << robot << int(KdlChainLayout::Compact);
        }
    }

    void agreesWithKdl() {
        QFETCH(QString, robot);
        QFETCH(int, layout);
        const Case c = makeCase(robot);
        if (!c.skip.isEmpty()) QSKIP(qPrintable(c.skip));
        const RobotModel& model = c.model;
        const int n = model.dof();
        KdlOracle kdl(model, c.effects, KdlChainLayout(layout));
        RobotData data(model);
        std::mt19937_64 rng(1234);

        double eB = 0, eC = 0, eG = 0, eTau = 0, eFd = 0, eT = 0, maxCond = 0;
        for (int sample = 0; sample < kSamples; ++sample) {
            const State s = randomState(rng, model);
            forwardKinematics(model, data, s.q);
            eT = std::max(eT, maxFrameError(data, kdl.framePoses(s.q)));

            computeMassMatrix(model, data);
            eB = std::max(eB, scaledError(data.B, kdl.massMatrix(s.q)));

            computeCoriolisMatrix(model, data, s.qd);
            const Eigen::VectorXd Cqd = data.C * s.qd;
            eC = std::max(eC, scaledError(Cqd, kdl.coriolis(s.q, s.qd)));

            computePotentialGradient(model, data, c.effects, s.q);
            eG = std::max(eG, scaledError(data.g, kdl.gravity(s.q)));

            const Eigen::VectorXd tau = inverseDynamics(model, data, c.effects, s.q, s.qd, s.qdd);
            eTau = std::max(eTau, scaledError(tau, kdl.inverseDynamics(s.q, s.qd, s.qdd)));

            const Eigen::VectorXd qdd = forwardDynamics(model, data, c.effects, s.q, s.qd, tau);
            eFd = std::max(eFd, scaledError(qdd, kdl.forwardDynamics(s.q, s.qd, tau)));

            Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(data.B, Eigen::EigenvaluesOnly);
            maxCond = std::max(maxCond, eig.eigenvalues().maxCoeff() / eig.eigenvalues().minCoeff());
        }
        qInfo("%-24s %-7s n=%d segs=%u  max err: T %.1e  B %.1e  Cqd %.1e  g %.1e  tau %.1e  qdd %.1e  (cond B <= %.1e)", qPrintable(robot),
              layout == int(KdlChainLayout::Exact) ? "exact" : "compact", n, kdl.chain().getNrOfSegments(), eT, eB, eC, eG, eTau, eFd,
              maxCond);
        QVERIFY2(eT <= kTol, qPrintable(QString("T_0i error %1").arg(eT)));
        QVERIFY2(eB <= kTol, qPrintable(QString("B error %1").arg(eB)));
        QVERIFY2(eC <= kTol, qPrintable(QString("C qd error %1").arg(eC)));
        QVERIFY2(eG <= kTol, qPrintable(QString("g error %1").arg(eG)));
        QVERIFY2(eTau <= kTol, qPrintable(QString("tau error %1").arg(eTau)));
        QVERIFY2(eFd <= kTolFd, qPrintable(QString("qdd error %1").arg(eFd)));
    }

    // The mapping is not vacuous: a wrong convention, a missing base or a mistaken
    // inertia would be caught. (Guards the test itself.)
    void detectsAWrongModel() {
        const RobotModel model = randomRobot(7, "RRPRPRR", DhConvention::Standard);
        RobotModel wrong = model;
        wrong.convention = DhConvention::Modified;
        RobotModel noBase = model;
        noBase.base = Eigen::Isometry3d::Identity();
        RobotModel flipped = model;
        flipped.joints[3].link.inertia(0, 1) *= -1;
        flipped.joints[3].link.inertia(1, 0) *= -1;
        KdlOracle kdl(model, kTiltedGravity);
        RobotData data(model);
        std::mt19937_64 rng(9);
        const State s = randomState(rng, model);
        for (const RobotModel* other : {&wrong, &noBase, &flipped}) {
            KdlOracle kdlOther(*other, kTiltedGravity);
            const Eigen::VectorXd tau = kdl.inverseDynamics(s.q, s.qd, s.qdd);
            QVERIFY(scaledError(kdlOther.inverseDynamics(s.q, s.qd, s.qdd), tau) > 1e-6);
        }
    }

    // The raw KDL calls fill the public buffers the Eigen calls read; an oracle moves.
    void rawCallsAndMove() {
        const RobotModel model = randomRobot(7, "RRPRPRR", DhConvention::Modified);
        KdlOracle first(model, kTiltedGravity, KdlChainLayout::Compact);
        KdlOracle kdl = std::move(first);
        std::mt19937_64 rng(10);
        const State s = randomState(rng, model);
        kdl.setState(s.q, s.qd);
        kdl.setAcceleration(s.qdd);
        QCOMPARE(kdl.kdlMassMatrix(), 0);
        QCOMPARE(kdl.kdlCoriolis(), 0);
        QCOMPARE(kdl.kdlGravity(), 0);
        QCOMPARE(kdl.kdlInverseDynamics(), 0);
        const Eigen::MatrixXd H = kdl.H.data;
        const Eigen::VectorXd tau = kdl.tauOut.data;
        QVERIFY(scaledError(tau, Eigen::VectorXd(H * s.qdd + kdl.c.data + kdl.g.data)) < 1e-12);
        kdl.setTorque(tau);
        QCOMPARE(kdl.kdlForwardDynamics(), 0);
        QVERIFY(scaledError(kdl.qddOut.data, s.qdd) < 1e-9);
        QCOMPARE(kdl.kdlFramePoses(), 0);
        QVERIFY(scaledError(kdl.massMatrix(s.q), H) == 0.0);
    }

    // KDL-independent sanity on the same robots: τ = B q̈ + C q̇ + g, Ḃ − 2C skew-symmetric.
    void independentSanity() {
        for (const char* name : {"random7 std", "random7 mod", "stanford"}) {
            const Case c = makeCase(name);
            const RobotModel& model = c.model;
            RobotData data(model);
            std::mt19937_64 rng(77);
            for (int sample = 0; sample < 20; ++sample) {
                const State s = randomState(rng, model);
                forwardKinematics(model, data, s.q);
                computeMassMatrix(model, data);
                computeCoriolisMatrix(model, data, s.qd);
                computePotentialGradient(model, data, c.effects, s.q);
                const Eigen::VectorXd lagrange = data.B * s.qdd + data.C * s.qd + data.g;
                const Eigen::VectorXd tau = rnea(model, data, c.effects, s.q, s.qd, s.qdd);
                QVERIFY(scaledError(tau, lagrange) < 1e-10);
                Eigen::MatrixXd Bdot = Eigen::MatrixXd::Zero(model.dof(), model.dof());
                for (int k = 0; k < model.dof(); ++k) Bdot += data.dB_dq[k] * s.qd[k];
                const Eigen::MatrixXd N = Bdot - 2 * data.C;
                QVERIFY(scaledError(N, Eigen::MatrixXd(-N.transpose())) < 1e-10);
            }
        }
    }
};

LL_TEST_APPLESS_MAIN(TestKdlOracle)

}  // namespace test_kdl_oracle
#include "test_kdl_oracle.moc"
