// `lagrangelab check` and the torque columns of `simulate --out`: the PUMA 560, the Panda
// and a typed Lagrangian pass every property with the residuals printed; the scene whose
// B becomes nearly singular fails the condition check and says where, and B at that pose,
// computed here by the numeric core, is as ill-conditioned as reported; bad input exits 2.
// The CSV's torque columns (named, with units) sum to its Q columns row by row.
#include "test_registry.hpp"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <Eigen/Eigenvalues>

#include "core/dynamics/mass_matrix.hpp"
#include "core/io/scene_file.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "process_run.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_check_cli {

using namespace ll;

namespace {

test::ProcessRun cli(const QStringList& args) { return test::runProcess(LL_CLI, args); }
QString example(const char* name) { return QString(LL_EXAMPLES_DIR) + "/" + name; }

const char* const kKeys[] = {"min_eigenvalue_B",       "max_condition_B",       "skew_residual",
                             "power_balance_residual", "newton_euler_residual", "energy_error"};

}  // namespace

class TestCheckCli : public QObject {
    Q_OBJECT

private slots:
    void passes_data() {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<bool>("robot");
        QTest::newRow("puma560") << example("puma560.json") << true;
        QTest::newRow("panda") << example("panda.json") << true;
        QTest::newRow("typed Lagrangian") << example("mass_spring_pair_lagrangian.json") << false;
    }
    void passes() {
        QFETCH(QString, scene);
        QFETCH(bool, robot);
        const auto r = cli({"check", scene, "--duration", "2", "--format", "json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(o["passed"].toBool(), true);
        for (const char* key : kKeys) {
            if (!robot && QString(key) == "newton_euler_residual") {
                QVERIFY(o[key].isNull());  // does not apply to a typed Lagrangian
                continue;
            }
            QVERIFY2(o[key].isDouble(), key);
        }
        QVERIFY(o["min_eigenvalue_B"].toDouble() > 0);
        QVERIFY(o["skew_residual"].toDouble() <= 1e-9);
        QVERIFY(o["power_balance_residual"].toDouble() <= 1e-9);
        if (robot) QVERIFY(o["newton_euler_residual"].toDouble() <= 1e-9);
        QVERIFY(o["energy_error"].toDouble() <= 1e-4);
        // the text says the same, one badge per property
        const auto text = cli({"check", scene, "--duration", "2"});
        QCOMPARE(text.exitCode, 0);
        QCOMPARE(text.out.count("PASS"), robot ? 6 : 5);
        QVERIFY(text.out.contains("passed: every property holds"));
        QVERIFY(text.out.contains("skew_residual = "));
    }

    // cond(B) passes 1e8 along the run: exit 1, and where. B at the reported pose,
    // from the numeric core here, has that condition number.
    void nearSingularMassReportsWhere() {
        const QString path = example("hard/near_singular_mass.json");
        const auto r = cli({"check", path, "--format", "json"});
        QCOMPARE(r.exitCode, 1);
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(o["passed"].toBool(), false);
        QVERIFY(o["max_condition_B"].toDouble() > 1e8);
        QJsonObject condition;
        for (const QJsonValue c : o["checks"].toArray())
            if (c.toObject()["key"] == "max_condition_B") condition = c.toObject();
        QCOMPARE(condition["passed"].toBool(), false);
        const QJsonArray qs = condition["q"].toArray();
        const Scene scene = loadScene(path.toStdString()).scene;
        QCOMPARE(qs.size(), scene.robot.dof());
        Eigen::VectorXd q(qs.size());
        for (int i = 0; i < qs.size(); ++i) q[i] = qs[i].toDouble();
        RobotData data(scene.robot);
        forwardKinematics(scene.robot, data, q);
        computeMassMatrix(scene.robot, data);
        const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(data.B).eigenvalues();
        const double cond = lambda(lambda.size() - 1) / lambda(0);
        QVERIFY(std::abs(cond - condition["value"].toDouble()) <= 1e-4 * cond);
        QVERIFY(condition["time"].toDouble() > 0);
        const auto text = cli({"check", path});
        QVERIFY(text.out.contains("FAIL  B is well conditioned"));
        QVERIFY(text.out.contains("worst at t = "));
    }

    void badInputExits2_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("says");
        QTest::newRow("format") << QStringList{"check", example("puma560.json"), "--format", "xml"} << "--format";
        QTest::newRow("duration") << QStringList{"check", example("puma560.json"), "--duration", "nan"} << "--duration";
        QTest::newRow("no scene") << QStringList{"check"} << "usage";
        QTest::newRow("missing file") << QStringList{"check", "/nonexistent/x.json"} << "/nonexistent/x.json";
    }
    void badInputExits2() {
        QFETCH(QStringList, args);
        QFETCH(QString, says);
        const auto r = cli(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(says.toUtf8()), r.err.constData());
    }

    // simulate --out: tau_inertial_i + tau_coriolis_i + tau_potential_i = Q_i on every row,
    // Q_i = Q_actuation_i + Q_viscous_i + Q_coulomb_i; units in the header; the residual in the summary.
    void simulateWritesTheTorques() {
        QTemporaryDir dir;
        const QString csv = dir.filePath("run.csv");
        const auto r = cli({"simulate", example("damped_pendulum.json"), "--duration", "2", "--out", csv});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.err.contains("torques: largest |B qdd + C qd + g - Q| = "));
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
        const QList<QByteArray> header = lines[0].split(',');
        const auto column = [&](const char* name) {
            const int c = static_cast<int>(header.indexOf(QByteArray(name)));
            if (c < 0) qFatal("no column %s", name);
            return c;
        };
        QCOMPARE(header.mid(0, 5).join(','), QByteArray("t,q1,qd1,Ekin,Epot"));
        const int inertial = column("tau_inertial_1 [N·m]"), coriolis = column("tau_coriolis_1 [N·m]"),
                  potential = column("tau_potential_1 [N·m]"), Q = column("Q_1 [N·m]"), actuation = column("Q_actuation_1 [N·m]"),
                  viscous = column("Q_viscous_1 [N·m]"), coulomb = column("Q_coulomb_1 [N·m]");
        double worst = 0, scale = 0, viscousSeen = 0;
        for (int k = 1; k < lines.size(); ++k) {
            const QList<QByteArray> v = lines[k].split(',');
            QCOMPARE(v.size(), header.size());
            const double sum = v[inertial].toDouble() + v[coriolis].toDouble() + v[potential].toDouble();
            worst = std::max(worst, std::abs(sum - v[Q].toDouble()));
            scale = std::max({scale, std::abs(v[inertial].toDouble()), std::abs(v[potential].toDouble())});
            QVERIFY(std::abs(v[Q].toDouble() - v[actuation].toDouble() - v[viscous].toDouble() - v[coulomb].toDouble()) <=
                    1e-12 * std::max(1.0, scale));
            viscousSeen = std::max(viscousSeen, std::abs(v[viscous].toDouble()));
        }
        QVERIFY(scale > 1);
        QVERIFY(viscousSeen > 0);
        QVERIFY(worst <= 1e-9 * scale);
    }
};

LL_TEST_GUILESS_MAIN(TestCheckCli)

}  // namespace test_check_cli
#include "test_check_cli.moc"
