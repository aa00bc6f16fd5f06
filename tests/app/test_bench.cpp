// lagrangelab-bench (app/bench): the benchmarks built beside the program and not
// installed. Its tables have the rows they promise, its numbers are plausible (no
// process is faster than zero, the budget column agrees with the medians), and bad
// arguments get one line and exit code 2. Timings themselves are never asserted.
#include "test_registry.hpp"

#include <QProcess>

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_bench {

namespace {

struct Run {
    int exitCode = -1;
    QByteArray out, err;
};

Run bench(const QStringList& args) {
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove("DISPLAY");
    env.remove("WAYLAND_DISPLAY");
    p.setProcessEnvironment(env);
    p.start(LL_BENCH, args);
    p.waitForFinished(600000);
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, p.readAllStandardOutput(), p.readAllStandardError()};
}

QString example(const char* name) { return QString(LL_EXAMPLES_DIR) + "/" + name; }

}  // namespace

class TestBench : public QObject {
    Q_OBJECT

private slots:
    void rhsTimesEachEffectSet() {
        const Run r = bench({"--rhs", "--batches", "3"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains("no effects") && r.out.contains("gravity only") && r.out.contains("all effects"));
        QVERIFY(r.out.contains("PUMA"));
    }

    void deriveReportsEveryMode() {
        const Run r = bench({"--derive", example("planar_2r.json"), "--batches", "1"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains("parameters") && r.out.contains("numeric") && r.out.contains("symbolic"));
        QVERIFY(r.out.contains("Planar 2R"));
    }

    // Whole `lagrangelab derive` processes: one row per scene with a median per format,
    // each a plausible time, marked '!' exactly when it is over the 0.5 s budget.
    void processTimesEveryFormat() {
        const Run r = bench({"--process", example("planar_2r.json"), example("simple_pendulum.json"), "--batches", "1"});
        QCOMPARE(r.exitCode, 0);
        int rows = 0;
        for (const QByteArray& line : r.out.split('\n')) {
            if (!line.startsWith("planar_2r") && !line.startsWith("simple_pendulum")) continue;
            ++rows;
            const QList<QByteArray> cells = line.simplified().split(' ');
            QCOMPARE(cells.size(), 8);  // name, six formats, verdict
            bool over = false;
            for (int f = 1; f <= 6; ++f) {
                const bool marked = cells[f].endsWith('!');
                const double seconds = (marked ? cells[f].chopped(1) : cells[f]).toDouble();
                QVERIFY2(seconds > 0 && seconds < 60, line.constData());
                QCOMPARE(marked, seconds > 0.5);
                over = over || marked;
            }
            QCOMPARE(cells[7], QByteArray(over ? "OVER" : "ok"));
        }
        QCOMPARE(rows, 2);
        const Run bad = bench({"--process", "--form", "tidy"});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY2(bad.err.startsWith("error: --form: ") && bad.err.contains("tidy"), bad.err.constData());
        QCOMPARE(bench({"--form", "structured"}).exitCode, 2);  // --form only with --process
    }

    void badArgumentsGiveExitCode2() {
        for (const char* batches : {"0", "-3", "2.5", "1e9"}) {  // a median needs whole batches (0 crashed)
            const Run r = bench({example("planar_2r.json"), "--batches", batches});
            QCOMPARE(r.exitCode, 2);
            QVERIFY2(r.err.startsWith("error: --batches: ") && r.err.contains(batches), r.err.constData());
        }
        const Run unknown = bench({"--frobnicate"});
        QCOMPARE(unknown.exitCode, 2);
        QVERIFY2(unknown.err.startsWith("error: "), unknown.err.constData());
        const Run help = bench({"--help"});
        QCOMPARE(help.exitCode, 0);
        QVERIFY(help.out.startsWith("usage: lagrangelab-bench"));
    }
};

LL_TEST_GUILESS_MAIN(TestBench)

}  // namespace test_bench
#include "test_bench.moc"
