// `lagrangelab accuracy` as a user runs it (table, CSV, headless PNG/SVG plot), the plot
// renderer in-process, `integrators` listing rosenbrock4, `bench --rhs`, and the cost
// line of every `simulate`.
#include "test_registry.hpp"

#include <QGuiApplication>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>

#include "core/io/scene_file.hpp"
#include "core/pipeline/scene_simulation.hpp"
#include "core/model/utf8_text.hpp"
#include "ui/paint/work_precision_plot.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_accuracy_cli {

class TestAccuracyCli : public QObject {
    Q_OBJECT

    struct Run {
        int exitCode;
        QByteArray out, err;
    };
    static Run run(const QStringList& args) {
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove("DISPLAY");  // the plot must render with no display at all
        env.remove("WAYLAND_DISPLAY");
        env.remove("QT_QPA_PLATFORM");
        p.setProcessEnvironment(env);
        p.start(LL_CLI, args);
        p.waitForFinished(300000);
        const Run r{p.exitCode(), p.readAllStandardOutput(), p.readAllStandardError()};
        if (r.exitCode == 2)  // every refusal is valid UTF-8
            QTest::qVerify(ll::isValidUtf8(r.err.toStdString()), "stderr is UTF-8", r.err.constData(), __FILE__, __LINE__);
        return r;
    }
    static QString example(const char* name) { return QString(LL_EXAMPLES_DIR) + "/" + name; }

    // Distinct colours in the image (a blank or text-only image has few).
    static int colourCount(const QImage& image) {
        QSet<QRgb> colours;
        for (int y = 0; y < image.height(); y += 2)
            for (int x = 0; x < image.width(); x += 2) colours.insert(image.pixel(x, y));
        return colours.size();
    }

private slots:
    void accuracyWritesTableCsvAndPlot() {
        QTemporaryDir dir;
        const QString png = dir.filePath("wp.png"), csv = dir.filePath("wp.csv");
        const Run r = run({"accuracy", example("simple_pendulum.json"), "--integrators", "rk4,dopri5,rosenbrock4", "--tolerances",
                           "1e-4..1e-7", "--steps", "1e-2,5e-3", "--duration", "2", "--repeats", "1", "--out", png, "--csv", csv});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY(r.out.contains("1 + |x_ref,i|"));  // says what "error" means
        QVERIFY(r.out.contains("reference: fehlberg78"));
        QCOMPARE(r.out.count("rosenbrock4"), 4);
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
        QCOMPARE(lines.size(), 1 + 1 + 2 + 4 + 4);  // header, reference, rk4 x2, two adaptive x4
        QVERIFY(lines[0].startsWith("integrator,adaptive,setting,completed,final_error"));
        const QList<QByteArray> row = lines[2].split(',');  // rk4 dt 1e-2
        QCOMPARE(row[0], QByteArray("rk4"));
        QVERIFY(row[4].toDouble() > 0 && row[4].toDouble() < 1e-3);
        QCOMPARE(row[9].toLong(), 200L);     // steps: 2 s / 1e-2
        QCOMPARE(row[11].toDouble(), 1e-2);  // step_seconds: the dt taken, beside the cost
        QVERIFY(r.out.contains("dt [s]"));
        const QImage image(png);
        QVERIFY(!image.isNull());
        QVERIFY(image.width() >= 1000 && image.height() >= 500);
        QVERIFY(colourCount(image) > 20);
    }

    void accuracyRejectsBadInput() {
        Run r = run({"accuracy", example("simple_pendulum.json"), "--integrators", "rk5"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.err.contains("unknown integrator 'rk5'"));
        r = run({"accuracy", example("simple_pendulum.json"), "--out", "plot.pdf"});
        QCOMPARE(r.exitCode, 2);
        r = run({"accuracy", example("simple_pendulum.json"), "--tolerances", "1e-3..x"});
        QCOMPARE(r.exitCode, 2);
    }

    void plotRendersSvgAndPngInProcess() {
        ll::Scene scene = ll::loadScene(example("simple_pendulum.json").toStdString()).scene;
        scene.effects.springs = {{0, 1e6, 0.0}};  // ω ≈ 1000 rad/s: the explicit Euler at dt = 0.01 blows up
        ll::WorkPrecisionSettings s;
        s.integrators = {"euler", "rk4", "dopri5"};
        s.tolerances = {1e-5, 1e-8};
        s.steps = {1e-2, 1e-4};  // euler and rk4 fail at 1e-2: the plot must say so, not break
        s.duration = 5.0;
        s.repeats = 1;
        const ll::WorkPrecisionResult r = ll::runWorkPrecision(scene, s);
        QTemporaryDir dir;
        QString error;
        QVERIFY2(ll::ui::saveWorkPrecisionPlot(r, dir.filePath("p.svg"), &error), qPrintable(error));
        QFile svg(dir.filePath("p.svg"));
        QVERIFY(svg.open(QIODevice::ReadOnly));
        const QByteArray text = svg.readAll();
        QVERIFY(text.contains("<svg") && text.contains("dopri5") && text.contains("2 runs stopped early"));
        QVERIFY(ll::ui::saveWorkPrecisionPlot(r, dir.filePath("p.png"), &error));
        QVERIFY(colourCount(QImage(dir.filePath("p.png"))) > 20);
        QVERIFY(!ll::ui::saveWorkPrecisionPlot(r, dir.filePath("p.bmp"), &error));
        QVERIFY(error.contains(".svg or .png"));
    }

    void integratorsListsRosenbrock() {
        const Run r = run({"integrators"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains("rosenbrock4"));
        QVERIFY(r.out.contains("stiff"));
    }

    void simulateReportsCostAndDrift() {
        const Run r = run({"simulate", example("simple_pendulum.json"), "--duration", "1"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.err.contains("right-hand-side evaluations"));
        QVERIFY(r.err.contains("per simulated second"));
        QVERIFY(r.err.contains("max |dE|/E"));
        // a fixed step that does not divide the duration: the summary says it
        const Run f = run({"simulate", example("simple_pendulum.json"), "--duration", "1", "--integrator", "rk4", "--dt", "0.003", "--out",
                           QTemporaryDir().filePath("x.csv")});
        QCOMPARE(f.exitCode, 0);
        QVERIFY2(f.err.contains("cost: 334 steps"), f.err.constData());
        QVERIFY2(f.err.contains("last shorter step of 0.001 s"), f.err.constData());
        QVERIFY2(f.err.contains("66 of 101 samples lie between step ends"), f.err.constData());
    }

    void stiffSceneStopsWithRecommendation() {
        const Run r =
            run({"simulate", example("hard/stiff_spring.json"), "--integrator", "dopri5", "--out", QTemporaryDir().filePath("x.csv")});
        QCOMPARE(r.exitCode, 3);
        QVERIFY2(r.err.contains("stiff") && r.err.contains("rosenbrock4"), r.err.constData());
    }
};

static int runAccuracyCli(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication app(argc, argv);
    TestAccuracyCli test;
    return QTest::qExec(&test, argc, argv);
}
LL_TEST_PROGRAM(runAccuracyCli)

}  // namespace test_accuracy_cli
#include "test_accuracy_cli.moc"
