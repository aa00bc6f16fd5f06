// The controller on the command line: `simulate --out` writes q_ref_i, e_i and the
// controller's terms with units, and they add up (e = q_ref − q, τ = the terms' sum = the
// Q the integrator used, K_p e = 100 e, V̇ = −q̇ᵀK_d q̇ for PD + g); `check` reports the
// tracking (computed torque with the exact model within 1e-6 rad, the Panda saturated);
// `compare-laws` runs the four laws, says why computed torque cannot drive the acrobot,
// and draws the plot; bad input (no controller, a wrong plot type, a bad gain) exits 2
// naming what is wrong.
#include "test_registry.hpp"

#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>
#include <QTemporaryDir>

#include "process_run.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_control_cli {

namespace {

ll::test::ProcessRun cli(const QStringList& args) { return ll::test::runProcess(LL_CLI, args); }
QString example(const char* name) { return QString(LL_EXAMPLES_DIR) + "/control/" + name; }

// The CSV as a header and rows of numbers.
struct Csv {
    QList<QByteArray> header;
    std::vector<std::vector<double>> rows;
    int column(const char* name) const {
        const int c = static_cast<int>(header.indexOf(QByteArray(name)));
        if (c < 0) qFatal("no column %s", name);
        return c;
    }
};
Csv readCsv(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) qFatal("cannot read %s", qPrintable(path));
    const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
    Csv csv;
    csv.header = lines[0].split(',');
    for (int k = 1; k < lines.size(); ++k) {
        std::vector<double> row;
        for (const QByteArray& v : lines[k].split(',')) row.push_back(v.toDouble());
        csv.rows.push_back(row);
    }
    return csv;
}

}  // namespace

class TestControlCli : public QObject {
    Q_OBJECT

private slots:
    void simulateWritesTheController() {
        QTemporaryDir dir;
        const QString path = dir.filePath("run.csv");
        const auto r = cli({"simulate", example("planar_2r_pd_gravity.json"), "--duration", "3", "--out", path});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const Csv csv = readCsv(path);
        QCOMPARE(csv.rows.size(), std::size_t(301));
        double worstError = 0, worstSum = 0, worstQ = 0, worstKp = 0, worstV = 0, scale = 0, vScale = 0;
        for (const auto& row : csv.rows) {
            QCOMPARE(row.size(), std::size_t(csv.header.size()));
            for (int i = 1; i <= 2; ++i) {
                const auto at = [&](const char* stem, const char* unit) {
                    return row[static_cast<std::size_t>(csv.column(qPrintable(QString("%1%2 [%3]").arg(stem).arg(i).arg(unit))))];
                };
                const double q = row[static_cast<std::size_t>(csv.column(qPrintable(QString("q%1").arg(i))))];
                worstError = std::max(worstError, std::abs(at("e_", "rad") - (at("q_ref_", "rad") - q)));
                const double sum = at("tau_ctrl_inertial_", "N·m") + at("tau_ctrl_coriolis_", "N·m") + at("tau_ctrl_gravity_", "N·m") +
                                   at("tau_ctrl_kp_", "N·m") + at("tau_ctrl_kd_", "N·m");
                worstSum = std::max(worstSum, std::abs(sum - at("tau_ctrl_", "N·m")));
                worstQ = std::max(worstQ, std::abs(at("Q_actuation_", "N·m") - at("tau_ctrl_", "N·m")));
                worstKp = std::max(worstKp, std::abs(at("tau_ctrl_kp_", "N·m") - 100 * at("e_", "rad")));
                scale = std::max(scale, std::abs(at("tau_ctrl_", "N·m")));
                QCOMPARE(at("tau_ctrl_inertial_", "N·m"), 0.0);  // PD + g has no B̂ q̈_d
            }
            const double Vdot = row[static_cast<std::size_t>(csv.column("Vdot [W]"))];
            const double minus = row[static_cast<std::size_t>(csv.column("minus_qdT_Kd_qd [W]"))];
            worstV = std::max(worstV, std::abs(Vdot - minus));
            vScale = std::max(vScale, std::abs(minus));
            QVERIFY(row[static_cast<std::size_t>(csv.column("V [J]"))] >= 0);
        }
        QVERIFY(scale > 10);
        QVERIFY(worstError <= 1e-15);
        QVERIFY(worstSum <= 1e-12 * scale);
        QVERIFY(worstQ <= 1e-12 * scale);
        QVERIFY(worstKp <= 1e-12 * scale);
        QVERIFY2(worstV <= 1e-8 * vScale, qPrintable(QString::number(worstV / vScale)));
        // JSON: the same columns, their units beside
        const QString json = dir.filePath("run.json");
        QCOMPARE(cli({"simulate", example("planar_2r_pd_gravity.json"), "--duration", "1", "--out", json}).exitCode, 0);
        QFile f(json);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QJsonObject o = QJsonDocument::fromJson(f.readAll()).object();
        QCOMPARE(o["units"].toObject()["e_1"].toString(), QString("rad"));
        QCOMPARE(o["units"].toObject()["tau_ctrl_kd_2"].toString(), QString("N·m"));
        QCOMPARE(o["units"].toObject()["Vdot"].toString(), QString("W"));
        QCOMPARE(o["q_ref_1"].toArray().size(), o["t"].toArray().size());
    }

    void checkReportsTheTracking() {
        const auto exact = cli({"check", example("puma560_computed_torque.json"), "--format", "json"});
        QVERIFY2(exact.exitCode == 0, exact.err.constData());
        const QJsonObject tracking = QJsonDocument::fromJson(exact.out).object()["tracking"].toObject();
        QCOMPARE(tracking["law"].toString(), QString("computed_torque"));
        QCOMPARE(tracking["max_error"].toArray().size(), 6);
        for (const QJsonValue& e : tracking["max_error"].toArray()) QVERIFY(e.toDouble() <= 1e-6);
        QCOMPARE(tracking["largest_saturated_fraction"].toDouble(), 0.0);
        const auto wrong = cli({"check", example("puma560_payload_unknown.json"), "--format", "json"});
        double largest = 0;
        for (const QJsonValue& e : QJsonDocument::fromJson(wrong.out).object()["tracking"].toObject()["max_error"].toArray())
            largest = std::max(largest, e.toDouble());
        QVERIFY(largest > 1e-2);  // the payload it does not know shows
        const auto saturated = cli({"check", example("panda_trapezoidal_saturation.json"), "--duration", "1.5"});
        QVERIFY2(saturated.exitCode == 0, saturated.err.constData());
        QVERIFY(saturated.out.contains("tracking (computed_torque, e = q_ref - q)"));
        QVERIFY(saturated.out.contains("largest saturated fraction: "));
        QVERIFY(saturated.out.contains("saturated "));
    }

    void compareLawsTableAndPlot() {
        QTemporaryDir dir;
        const QString png = dir.filePath("laws.png");
        const auto r = cli({"compare-laws", example("acrobot_pd_elbow.json"), "--duration", "3", "--out", png});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY(r.out.contains("computed_torque  not possible: computed torque needs a torque on every joint: 1 of the 2 joints"));
        for (const char* law : {"pd ", "pd_gravity ", "feedforward "}) QVERIFY2(r.out.contains(law), law);
        QImage image(png);
        QCOMPARE(image.size(), QSize(1500, 640));
        QSet<QRgb> colours;
        for (int y = 0; y < image.height(); y += 2)
            for (int x = 0; x < image.width(); x += 2) colours.insert(image.pixel(x, y) & 0xffffff);
        // the law colours are drawn (blue pd, orange pd_gravity, red feedforward)
        for (QRgb law : {QRgb(0x1f77b4), QRgb(0xff7f0e), QRgb(0xd62728)}) QVERIFY(colours.contains(law));
        // PD leaves the 2R short of q* by g/K_p; PD + g and computed torque do not
        const auto two = cli({"compare-laws", example("planar_2r_pd.json"), "--format", "json"});
        QCOMPARE(two.exitCode, 0);
        const QJsonArray laws = lawsOf(two.out);
        QCOMPARE(laws.size(), 4);
        const auto finalRms = [&](int i) { return laws[i].toObject()["rms_error"].toArray()[0].toDouble(); };
        QVERIFY(finalRms(0) > 2 * finalRms(1));
        QVERIFY(laws[2].toObject()["possible"].toBool());
    }

    void badInputExits2_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("says");
        QTest::newRow("no controller") << QStringList{"compare-laws", QString(LL_EXAMPLES_DIR) + "/planar_2r.json"}
                                       << "no controller to compare";
        QTest::newRow("plot type") << QStringList{"compare-laws", example("planar_2r_pd.json"), "--out", "x.txt"} << "x.txt";
        QTest::newRow("format") << QStringList{"compare-laws", example("planar_2r_pd.json"), "--format", "xml"} << "xml";
        QTest::newRow("duration") << QStringList{"compare-laws", example("planar_2r_pd.json"), "--duration", "nan"} << "duration";
    }
    void badInputExits2() {
        QFETCH(QStringList, args);
        QFETCH(QString, says);
        const auto r = cli(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(says.toUtf8()), r.err.constData());
        QCOMPARE(r.err.count('\n'), 1);
    }

    void aBadGainIsNamed() {
        QTemporaryDir dir;
        QFile in(example("planar_2r_pd.json"));
        QVERIFY(in.open(QIODevice::ReadOnly));
        QByteArray text = in.readAll();
        text.replace("\"kp\": [\n        100,\n        100\n      ]", "\"kp\": [100, -5]");
        QVERIFY(text.contains("-5"));
        QFile out(dir.filePath("bad.json"));
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(text);
        out.close();
        for (const char* command : {"simulate", "check", "compare-laws"}) {
            const auto r = cli({command, out.fileName()});
            QCOMPARE(r.exitCode, 2);
            QVERIFY2(r.err.contains("effects.control.kp[1]"), r.err.constData());
        }
    }

private:
    static QJsonArray lawsOf(const QByteArray& out) { return QJsonDocument::fromJson(out).object()["laws"].toArray(); }
};

LL_TEST_GUILESS_MAIN(TestControlCli)

}  // namespace test_control_cli
#include "test_control_cli.moc"
