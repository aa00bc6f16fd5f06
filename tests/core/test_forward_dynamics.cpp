// Forward dynamics: the course notes' mass–spring pair, inverse(forward(τ)) = τ,
// a singular B named by joint, and no heap allocation per evaluation.
#include "test_registry.hpp"

#include <atomic>
#include <cstdlib>
#include <new>

#include "core/dynamics/forward_dynamics.hpp"
#include "core/dynamics/inverse_dynamics.hpp"
#include "test_support.hpp"

// Count every heap allocation in this process, to show that a dynamics evaluation makes none.
// The replacement is the process's, so it counts for every test of tests/core's program;
// it only counts, malloc and free do the work. Every form of new and delete that does not
// take an alignment is replaced, so that no pair is split between ours and the library's
// (or AddressSanitizer's): std::stable_sort's buffer comes from the nothrow new and goes
// back through the sized delete, which with only the plain new replaced was an
// alloc-dealloc mismatch under scripts/lab asan.
static std::atomic<long> g_allocations{0};
static void* counted(std::size_t size) noexcept {
    ++g_allocations;
    return std::malloc(size ? size : 1);
}
void* operator new(std::size_t size) {
    if (void* p = counted(size)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
    if (void* p = counted(size)) return p;
    throw std::bad_alloc();
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return counted(size); }
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept { return counted(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_forward_dynamics {

using namespace ll;

class TestForwardDynamics : public QObject {
    Q_OBJECT
private slots:
    // Course notes: I1θ̈1 + K1θ1 + K2(θ1−θ2) = 0 and I2θ̈2 − K2(θ1−θ2) = τ, with
    // θ1 = q1, θ2 = q1 + q2; τ on θ2 is Q = (τ, τ) in the relative coordinates.
    void massSpringPairMatchesCourseNotes() {
        const test::MassSpringPair p;
        const RobotModel robot = p.model();
        const Effects effects = p.effects();
        RobotData data(robot);
        std::mt19937 rng(51);
        for (int trial = 0; trial < 100; ++trial) {
            const Eigen::VectorXd q = test::randomVector(rng, 2, 1.0), qd = test::randomVector(rng, 2, 2.0);
            const double tau = test::randomVector(rng, 1, 3.0)[0];
            const Eigen::Vector2d Q(tau, tau);
            const Eigen::VectorXd qdd = forwardDynamics(robot, data, effects, q, qd, Q);
            const double th1 = q[0], th2 = q[0] + q[1], thdd1 = qdd[0], thdd2 = qdd[0] + qdd[1];
            QVERIFY(std::abs(p.I1 * thdd1 + p.K1 * th1 + p.K2 * (th1 - th2)) < 1e-12);
            QVERIFY(std::abs(p.I2 * thdd2 - p.K2 * (th1 - th2) - tau) < 1e-12);
        }
    }

    void inverseOfForwardIsIdentity() {
        for (DhConvention convention : {DhConvention::Standard, DhConvention::Modified}) {
            std::mt19937 rng(52);
            const int n = 7;
            const RobotModel robot = test::randomRobot(rng, n, convention);
            Effects effects;
            effects.gravity = Eigen::Vector3d(0, 0, -9.81);
            effects.springs = {{3, 20.0, 0.0}};
            RobotData data(robot);
            for (int trial = 0; trial < 100; ++trial) {
                const Eigen::VectorXd q = test::randomVector(rng, n, 3.0), qd = test::randomVector(rng, n, 3.0),
                                      tau = test::randomVector(rng, n, 20.0);
                const Eigen::VectorXd qdd = forwardDynamics(robot, data, effects, q, qd, tau);
                const Eigen::VectorXd back = inverseDynamics(robot, data, effects, q, qd, qdd);
                QVERIFY2(test::scaledError(back, tau) < 1e-10, qPrintable(QString::number(test::scaledError(back, tau))));
            }
        }
    }

    void singularMassMatrixNamesTheJoint() {
        // Joint 2 is coaxial with joint 1 and link 1 is massless: joint 2 moves
        // nothing that joint 1 does not, so B is singular and joint 2 is to blame.
        RobotModel robot;
        robot.joints.resize(3);
        robot.joints[1].link.inertia(2, 2) = 0.0;
        robot.joints[2].dh.alpha = 1.0;
        robot.joints[2].dh.a = 0.5;
        robot.joints[2].link.mass = 1.0;
        robot.joints[2].link.inertia.diagonal() << 0.1, 0.1, 0.1;
        RobotData data(robot);
        const Eigen::VectorXd zero = Eigen::VectorXd::Zero(3);
        try {
            forwardDynamics(robot, data, Effects{}, Eigen::Vector3d(0.1, 0.2, 0.3), zero, zero);
            QFAIL("expected SingularMassMatrix");
        } catch (const SingularMassMatrix& e) {
            QCOMPARE(e.joint(), 1);
            QVERIFY(QString(e.what()).contains("joint 2"));
        }
    }

    void evaluationAllocatesNothing() {
        std::mt19937 rng(53);
        const RobotModel robot = test::randomRobot(rng, 6, DhConvention::Standard);
        Effects effects;
        effects.gravity = Eigen::Vector3d(0, 0, -9.81);
        effects.springs = {{1, 5.0, 0.0}};
        RobotData data(robot);
        const Eigen::VectorXd q = test::randomVector(rng, 6, 3.0), qd = test::randomVector(rng, 6, 3.0),
                              tau = test::randomVector(rng, 6, 3.0);
        forwardDynamics(robot, data, effects, q, qd, tau);  // warm up
        const long before = g_allocations.load();
        for (int i = 0; i < 100; ++i) {
            forwardDynamics(robot, data, effects, q, qd, tau);
            inverseDynamics(robot, data, effects, q, qd, data.qdd);
        }
        QCOMPARE(g_allocations.load() - before, 0L);
    }
};

LL_TEST_APPLESS_MAIN(TestForwardDynamics)

}  // namespace test_forward_dynamics
#include "test_forward_dynamics.moc"
