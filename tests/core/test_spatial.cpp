// Spatial algebra identities the dynamics rely on, against their definitions.
#include "test_registry.hpp"

#include "core/math/spatial.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_spatial {

using namespace ll;

namespace {
Vector6d random6(std::mt19937& rng) { return test::randomVector(rng, 6, 2.0); }
}  // namespace

class TestSpatial : public QObject {
    Q_OBJECT
private slots:
    // The kinetic energy ½ vᵀ I v of a body at the origin equals the textbook
    // ½ m |v_c|² + ½ ωᵀ I_c ω with v_c = v_O + ω × p_c.
    void inertiaGivesTheTextbookKineticEnergy() {
        std::mt19937 rng(1);
        for (int k = 0; k < 50; ++k) {
            const double m = 0.5 + k * 0.1;
            const Eigen::Vector3d pc = test::randomVector(rng, 3, 1.0);
            const Eigen::Matrix3d Ic = test::randomInertia(rng);
            const SpatialInertia I = spatialInertiaAtOrigin(m, pc, Ic);
            const Vector6d v = random6(rng);
            const Eigen::Vector3d w = angular(v), vc = linear(v) + w.cross(pc);
            const double textbook = 0.5 * m * vc.squaredNorm() + 0.5 * w.dot(Ic * w);
            QVERIFY(std::abs(0.5 * v.dot(I * v) - textbook) < 1e-12 * std::max(1.0, textbook));
        }
    }

    void inertiaIsSymmetric() {
        std::mt19937 rng(2);
        const SpatialInertia I = spatialInertiaAtOrigin(2.0, test::randomVector(rng, 3, 1.0), test::randomInertia(rng));
        for (int k = 0; k < 50; ++k) {
            const Vector6d a = random6(rng), b = random6(rng);
            QVERIFY(std::abs(a.dot(I * b) - b.dot(I * a)) < 1e-12);
        }
    }

    // m · (v ×* f) = −(v × m) · f: the duality the Christoffel derivatives use.
    void crossProductsAreDual() {
        std::mt19937 rng(3);
        for (int k = 0; k < 50; ++k) {
            const Vector6d m = random6(rng), v = random6(rng), f = random6(rng);
            QVERIFY(std::abs(m.dot(crossForce(v, f)) + crossMotion(v, m).dot(f)) < 1e-12);
            QVERIFY(crossMotion(v, v).norm() < 1e-15);
        }
    }

    // A rigid motion carries the inertia: İ = v×* I − I v×, checked by moving the body
    // along a screw for a small time and differencing.
    void inertiaRateUnderMotion() {
        std::mt19937 rng(4);
        const double m = 1.7;
        const Eigen::Vector3d pc = test::randomVector(rng, 3, 1.0);
        const Eigen::Matrix3d Ic = test::randomInertia(rng);
        const Vector6d v = random6(rng), probe = random6(rng);
        const auto moved = [&](double t) {  // pose after time t of the motion v (about the origin)
            const Eigen::Vector3d w = angular(v);
            const Eigen::Matrix3d R = Eigen::AngleAxisd(w.norm() * t, w.normalized()).toRotationMatrix();
            // a point x moves as ẋ = ω × x + v_O, i.e. x(t) = R x + ∫ R v_O
            Eigen::Vector3d shift = Eigen::Vector3d::Zero();
            const int steps = 200;
            for (int s = 0; s < steps; ++s) {
                const double tau = (s + 0.5) / steps * t;
                shift += Eigen::AngleAxisd(w.norm() * tau, w.normalized()).toRotationMatrix() * linear(v) * (t / steps);
            }
            return spatialInertiaAtOrigin(m, R * pc + shift, R * Ic * R.transpose());
        };
        const double h = 1e-5;
        const Vector6d rate = (moved(h) * probe - moved(-h) * probe) / (2 * h);
        const SpatialInertia I = spatialInertiaAtOrigin(m, pc, Ic);
        const Vector6d expected = crossForce(v, I * probe) - I * crossMotion(v, probe);
        QVERIFY2((rate - expected).norm() < 1e-6 * std::max(1.0, expected.norm()), qPrintable(QString::number((rate - expected).norm())));
    }
};

LL_TEST_APPLESS_MAIN(TestSpatial)

}  // namespace test_spatial
#include "test_spatial.moc"
