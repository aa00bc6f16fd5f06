// `lagrangelab report SCENE --out DIR` as a student runs it, headless: every file the
// bundle names is there and reads back — the CSV's columns, units and values (E = E_kin +
// E_pot in every row), the SVG plots (they render, with ink), the PDF, the scene's bytes
// unchanged, the slide video's size and frame count (ffprobe) — and bad options exit 2.
#include "test_registry.hpp"

#include <QDir>
#include <QImage>
#include <QPainter>
#include <QProcess>
#include <QSvgRenderer>
#include <QTemporaryDir>

#include "process_run.hpp"
#include "ui/document/lab_report.hpp"  // the bundle's contents, as documented there

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_report_cli {

class TestReportCli : public QObject {
    Q_OBJECT
    using Run = ll::test::ProcessRun;
    static Run run(const QStringList& args) {  // headless, as a student's shell without X
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove("DISPLAY");
        env.remove("WAYLAND_DISPLAY");
        return ll::test::runProcess(LL_CLI, args, {}, env);
    }
    static QString example(const char* name) { return QString(LL_EXAMPLES_DIR) + "/" + name; }
    static QByteArray bytes(const QString& path) {
        QFile f(path);
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    }

private slots:
    void bundleOfTheTwoLinkArm_data() {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<int>("n");
        QTest::addColumn<QString>("unit");
        QTest::newRow("planar 2R") << "planar_2r.json" << 2 << "rad";
        QTest::newRow("typed Lagrangian") << "mass_spring_pair_lagrangian.json" << 2 << "";
    }
    void bundleOfTheTwoLinkArm() {
        QFETCH(QString, scene);
        QFETCH(int, n);
        QFETCH(QString, unit);
        QTemporaryDir dir;
        const QString out = dir.filePath("report/nested");  // made when missing
        const Run r = run({"report", example(qPrintable(scene)), "--out", out, "--duration", "2"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QStringList expected{"derivation.pdf", "trajectory.csv", "energy.svg", "joints.svg", scene, "slide.mp4", "index.md"};
        QStringList printed;
        for (const QByteArray& line : r.out.trimmed().split('\n')) printed << QFileInfo(QString::fromUtf8(line)).fileName();
        QCOMPARE(printed, expected);
        const QString index = QString::fromUtf8(bytes(out + "/index.md"));
        for (const QString& f : expected) {
            QVERIFY2(QFileInfo(out + "/" + f).size() > 0, qPrintable(f));
            if (f != "index.md") QVERIFY2(index.contains("[" + f + "](" + f + ")"), qPrintable(f));
        }
        QVERIFY(bytes(out + "/derivation.pdf").startsWith("%PDF-"));
        QCOMPARE(bytes(out + "/" + scene), bytes(example(qPrintable(scene))));

        // The CSV reads back: its header names every column's unit, E = E_kin + E_pot.
        const QList<QByteArray> lines = bytes(out + "/trajectory.csv").trimmed().split('\n');
        const QStringList header = QString::fromUtf8(lines.first()).split(',');
        QCOMPARE(header.size(), 1 + 2 * n + 4);
        QCOMPARE(header.first(), QString("t [s]"));
        QVERIFY(header.endsWith("W [J]") && header.contains("Ekin [J]") && header.contains("Epot [J]"));
        if (!unit.isEmpty()) {
            QVERIFY2(header[1].endsWith("[" + unit + "]"), qPrintable(header[1]));
            QVERIFY2(header[1 + n].endsWith("[" + unit + "/s]"), qPrintable(header[1 + n]));
        }
        QVERIFY(lines.size() > 20);
        double lastT = -1;
        const int ekin = header.indexOf("Ekin [J]");
        for (int k = 1; k < lines.size(); ++k) {
            const QList<QByteArray> cells = lines[k].split(',');
            QCOMPARE(cells.size(), header.size());
            bool ok = true;
            const double t = cells[0].toDouble(&ok);
            QVERIFY(ok && t > lastT);
            lastT = t;
            const double Ek = cells[ekin].toDouble(), Ep = cells[ekin + 1].toDouble(), E = cells[ekin + 2].toDouble();
            QVERIFY(std::abs(Ek + Ep - E) <= 1e-9 * std::max(1.0, std::abs(E)));
        }
        QVERIFY(std::abs(lastT - 2.0) < 1e-9);

        // The plots are vector SVG that render with curves on them.
        for (const char* plot : {"energy.svg", "joints.svg"}) {
            QSvgRenderer svg(out + "/" + plot);
            QVERIFY2(svg.isValid(), plot);
            QImage image(800, 450, QImage::Format_RGB32);
            image.fill(Qt::white);
            QPainter painter(&image);
            svg.render(&painter);
            painter.end();
            long coloured = 0;
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x) {
                    const QColor c = image.pixelColor(x, y);
                    coloured += c.saturation() > 120 && c.value() > 80;
                }
            QVERIFY2(coloured > 1500, qPrintable(QString("%1: %2 coloured pixels").arg(plot).arg(coloured)));
            QVERIFY(!bytes(out + "/" + plot).contains("<image"));  // drawn, not a picture of a plot
        }

        // The slide: 1280×720, 30 frames per simulated second.
        QProcess probe;
        probe.start("ffprobe", {"-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                                "stream=width,height,nb_read_frames", "-of", "csv=p=0", out + "/slide.mp4"});
        QVERIFY(probe.waitForFinished(60000));
        QCOMPARE(QString::fromUtf8(probe.readAllStandardOutput()).trimmed(), QString("1280,720,60"));
    }

    void badOptions() {
        Run r = run({"report", example("planar_2r.json"), "--out", "/proc/lagrangelab-report"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.startsWith("error: --out /proc/lagrangelab-report:"), r.err.constData());
        r = run({"report", example("planar_2r.json")});
        QCOMPARE(r.exitCode, 2);
        r = run({"report", example("planar_2r.json"), "--out", QDir::tempPath() + "/x", "--duration", "nan"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.startsWith("error: --duration"), r.err.constData());
    }
};

LL_TEST_MAIN(TestReportCli)

}  // namespace test_report_cli
#include "test_report_cli.moc"
