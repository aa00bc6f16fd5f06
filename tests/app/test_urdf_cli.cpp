// lagrangelab import and export-urdf run as a user runs them: the PUMA-like test robot
// imported to a scene that eval reads, with its table and each frame's case on stderr;
// the scene written back as URDF and imported again to the same B, C and g; bad input
// refused in one line naming the file or the option, exit 2.
#include "test_registry.hpp"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include "process_run.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_urdf_cli {

using ll::test::runProcess;

namespace {

ll::test::ProcessRun lagrangelab(const QStringList& args) { return runProcess(LL_CLI, args, {}, ll::test::freshLocaleEnvironment()); }

QString testRobot(const char* name) { return QString(LL_SOURCE_DIR) + "/tests/urdf/" + name; }

// eval's B, C q̇ and g of `scene` at one state, as one flat list of numbers.
QList<double> dynamicsAt(const QString& scene) {
    const auto r = lagrangelab({"eval", scene, "--q", "0.3,-0.7,0.4,1.1,-0.5,0.9", "--qd", "0.5,0.2,-0.4,0.1,0.3,-0.6"});
    if (r.exitCode != 0) qFatal("eval %s: %s", qPrintable(scene), r.err.constData());
    const QJsonObject o = QJsonDocument::fromJson(r.out).object();
    QList<double> numbers;
    for (const QJsonValue& row : o["B"].toArray())
        for (const QJsonValue& v : row.toArray()) numbers << v.toDouble();
    const QJsonArray C = o["C"].toArray();
    const double qd[] = {0.5, 0.2, -0.4, 0.1, 0.3, -0.6};
    for (const QJsonValue& row : C) {
        double sum = 0;
        for (int j = 0; j < 6; ++j) sum += row.toArray()[j].toDouble() * qd[j];
        numbers << sum;
    }
    for (const QJsonValue& v : o["g"].toArray()) numbers << v.toDouble();
    return numbers;
}

}  // namespace

class TestUrdfCli : public QObject {
    Q_OBJECT
private slots:
    void importExportImport() {
        QTemporaryDir dir;
        const QString scene = dir.filePath("puma.json"), urdf = dir.filePath("puma.urdf"), again = dir.filePath("again.json");
        const auto imported = lagrangelab({"import", testRobot("puma_like.urdf"), "--out", scene});
        QVERIFY2(imported.exitCode == 0, imported.err.constData());
        const QString table = QString::fromUtf8(imported.err);
        QVERIFY2(table.contains("puma_like: links base to flange, 6 joints, standard DH"), qPrintable(table));
        QVERIFY2(table.contains("1. j1, revolute, 0, 1.5708, 0.672, 0, intersecting axes"), qPrintable(table));
        QVERIFY2(table.contains("2. j2, revolute, 0.4318, 0, 0, 0, parallel axes"), qPrintable(table));
        QVERIFY2(table.contains("3. j3, revolute, 0.0203, -1.5708, 0.15005, 0, skew axes"), qPrintable(table));
        QVERIFY2(table.contains("6. j6, revolute, 0, 0, 0.056, 0, the last frame"), qPrintable(table));
        const auto exported = lagrangelab({"export-urdf", scene, "--out", urdf});
        QVERIFY2(exported.exitCode == 0, exported.err.constData());
        const auto back = lagrangelab({"import", urdf, "--out", again, "--convention", "modified"});
        QVERIFY2(back.exitCode == 0, back.err.constData());
        const QList<double> a = dynamicsAt(scene), b = dynamicsAt(again);
        QCOMPARE(a.size(), 36 + 6 + 6);
        double worst = 0, largest = 0;
        for (int i = 0; i < a.size(); ++i) {
            worst = std::max(worst, std::abs(a[i] - b[i]));
            largest = std::max(largest, std::abs(a[i]));
        }
        QVERIFY2(worst <= 1e-9 * std::max(1.0, largest), qPrintable(QString::number(worst)));
    }

    void badInputIsOneLineAndExitCode2_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("expected");
        QTest::newRow("no such file") << QStringList{"import", "/nonexistent/robot.urdf", "--out", "x.json"} << "/nonexistent/robot.urdf: ";
        QTest::newRow("bad convention") << QStringList{"import", testRobot("planar_2r.urdf"), "--out", "x.json", "--convention", "craig"}
                                        << "--convention: expected standard or modified, got 'craig'";
        QTest::newRow("unknown tip") << QStringList{"import", testRobot("planar_2r.urdf"), "--out", "x.json", "--tip", "hand"}
                                     << "--tip: no link named hand";
        QTest::newRow("unwritable out") << QStringList{"import", testRobot("planar_2r.urdf"), "--out", "/nonexistent/x.json"}
                                        << "/nonexistent/x.json";
        QTest::newRow("not URDF") << QStringList{"import", QString(LL_EXAMPLES_DIR) + "/planar_2r.json", "--out", "x.json"}
                                  << "planar_2r.json: not a URDF robot";
        QTest::newRow("a typed Lagrangian") << QStringList{"export-urdf", QString(LL_EXAMPLES_DIR) + "/mass_spring_pair_lagrangian.json",
                                                           "--out", "x.urdf"}
                                            << "a typed Lagrangian has no links and joints to write as URDF";
    }
    void badInputIsOneLineAndExitCode2() {
        QFETCH(QStringList, args);
        QFETCH(QString, expected);
        QTemporaryDir dir;
        for (QString& a : args)
            if (a == "x.json" || a == "x.urdf") a = dir.filePath(a);
        const auto r = lagrangelab(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(expected.toUtf8()), r.err.constData());
        QVERIFY2(r.err.count('\n') <= 2, r.err.constData());  // the line, and a hint at most
    }
};

LL_TEST_GUILESS_MAIN(TestUrdfCli)

}  // namespace test_urdf_cli
#include "test_urdf_cli.moc"
